// An RMQ quantization range in which the flat ground's value is a code (see rmq_atom_range.h).
#include "libbake/glint/rmq_atom_range.h"

#include <cmath>

namespace mbk {
namespace {

// The smallest double >= x > 0 with at most `bits` significant bits.
double round_up_to_bits(double x, int bits) {
  int e = 0;
  const double m = std::frexp(x, &e);  // x = m 2^e, m in [0.5, 1)
  return std::ldexp(std::ceil(std::ldexp(m, bits)), e - bits);
}

}  // namespace

RmqRange rmq_range_with_exact_value(const RmqRange& data, std::optional<double> atom, uint32_t bits) {
  if (!atom || !(*atom >= data.lo && *atom <= data.hi) || !(data.hi > data.lo)) return data;
  const uint32_t q_max = rmq_code_max(bits);
  const double quantum = round_up_to_bits((data.hi - data.lo) / (q_max - 1), kRmqAtomQuantumBits);
  if (!(quantum > 0.0) || !std::isfinite(quantum)) return data;
  const double q0 = std::ceil((*atom - data.lo) / quantum);
  if (!(q0 >= 0.0 && q0 <= q_max)) return data;
  RmqRange r;
  r.lo = *atom - q0 * quantum;
  r.hi = r.lo + q_max * quantum;
  const RmqQuantizer check(r, bits);
  if (!(r.lo <= data.lo && r.hi >= data.hi) || r.quantum(bits) != quantum || check.value(uint32_t(q0)) != *atom)
    return data;
  return r;
}

}  // namespace mbk
