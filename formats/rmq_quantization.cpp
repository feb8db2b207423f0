// The conservative quantizer of the `rmq` kind (see rmq_quantization.h).
#include "formats/rmq_quantization.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "formats/error.h"
#include "formats/number_text.h"

namespace mbk {

double RmqRange::quantum(uint32_t bits) const { return (hi - lo) / rmq_code_max(bits); }

double rmq_dequantize(uint32_t code, const RmqRange& range, uint32_t bits) {
  const uint32_t q_max = rmq_code_max(bits);
  if (code == 0) return range.lo;
  if (code >= q_max) return range.hi;
  return std::min(range.hi, range.lo + code * range.quantum(bits));
}

uint32_t rmq_quantize_up(double v, const RmqRange& range, uint32_t bits) {
  if (!(v >= range.lo && v <= range.hi))
    throw Error(ExitCode::runtime_failure, "internal: rmq value " + number_text(v) + " outside its range [" +
                                               number_text(range.lo) + ", " + number_text(range.hi) + "]");
  const uint32_t q_max = rmq_code_max(bits);
  auto value = [&](uint32_t q) { return rmq_dequantize(q, range, bits); };
  // Fast path: the arithmetic guess is almost always the answer (at most one code off after rounding).
  const double quantum = range.quantum(bits);
  if (quantum > 0.0 && std::isfinite(quantum)) {
    const double guess = std::ceil((v - range.lo) / quantum);
    const uint32_t g = uint32_t(std::clamp(guess, 0.0, double(q_max)));
    for (uint32_t q = g > 0 ? g - 1 : 0; q <= std::min(g + 1, q_max); ++q)
      if (value(q) >= v) {
        if (q == 0 || value(q - 1) < v) return q;
        break;
      }
  }
  // Robust path (ranges so narrow that consecutive codes share a value, or an off guess): binary search for
  // the smallest q with value(q) >= v; value(q_max) = hi >= v, so it exists.
  uint32_t lo = 0, hi = q_max;
  while (lo < hi) {
    const uint32_t mid = lo + (hi - lo) / 2;
    if (value(mid) >= v)
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

uint32_t rmq_quantize_down(double v, const RmqRange& range, uint32_t bits) {
  const uint32_t up = rmq_quantize_up(v, range, bits);
  // value(up) >= v; if it is not v itself, then up > 0 (value(0) = lo <= v) and value(up - 1) < v.
  return rmq_dequantize(up, range, bits) == v ? up : up - 1;
}

}  // namespace mbk
