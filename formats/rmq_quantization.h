// The conservative quantizer of the `rmq` asset kind (formats/SPEC.md, "Kind 3: rmq"): how a stored code
// becomes a normal component, and how a bake picks codes so that stored bounds always contain the truth.
//
// A component's range [lo, hi] (derived from the data, stored in the asset) is cut into Q = 2^bits - 1 steps
// of one quantum (hi - lo) / Q. Reading a code q (0 <= q <= Q) gives, in double:
//
//   value(0) = lo,   value(Q) = hi,   value(q) = min(hi, lo + q * ((hi - lo) / Q)) otherwise.
//
// The two ends are exact (a plain lo + Q * quantum can miss hi by an ulp, and a maximum equal to hi would
// then have no code that bounds it), and value() never decreases with q (each operation is monotone).
// A minimum v is stored as quantize_down(v): a code whose value is <= v; a maximum as quantize_up(v): the
// smallest code whose value is >= v. Both are within one quantum of v (up to double rounding), and
// quantize_down(v) <= quantize_up(v), so an interval's codes are ordered whenever its ends are.
// Both functions are monotone in v, so min/max commute with them: the quantized minimum of a set is the
// minimum of its quantized values. The RMQ bake relies on that to build coarser levels from codes alone.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace mbk {

struct RmqRange {
  double lo = 0.0, hi = 0.0;
  double quantum(uint32_t bits) const;  // (hi - lo) / Q
};

inline constexpr uint32_t rmq_code_max(uint32_t bits) { return (1u << bits) - 1u; }

// The value of a code (formula above). Requires code <= Q and a finite range with lo <= hi.
double rmq_dequantize(uint32_t code, const RmqRange& range, uint32_t bits);

// The smallest code whose value is >= v. Requires lo <= v <= hi (Error(runtime_failure) otherwise).
uint32_t rmq_quantize_up(double v, const RmqRange& range, uint32_t bits);
// quantize_up(v) when its value is exactly v, else the code just below it: the largest code whose value is
// <= v among those not above quantize_up(v). Same requirement.
uint32_t rmq_quantize_down(double v, const RmqRange& range, uint32_t bits);

// rmq_dequantize / rmq_quantize_up / rmq_quantize_down for many values of one range: the quantum and its
// reciprocal computed once, the common case inline and without a division (the guess ceil((v - lo) / quantum)
// is checked against value(); when rounding put it off, a binary search).
class RmqQuantizer {
 public:
  RmqQuantizer(const RmqRange& range, uint32_t bits)
      : range_(range),
        bits_(bits),
        q_max_(rmq_code_max(bits)),
        quantum_(range.quantum(bits)),
        inverse_(1.0 / quantum_),
        fast_(quantum_ > 0.0 && std::isfinite(quantum_) && std::isfinite(inverse_)) {}

  double value(uint32_t q) const {
    if (q == 0) return range_.lo;
    if (q >= q_max_) return range_.hi;
    return std::min(range_.hi, range_.lo + q * quantum_);
  }
  uint32_t up(double v) const {
    if (fast_ && v >= range_.lo && v <= range_.hi) {
      // floor((v - lo) / quantum) by truncation (the argument is >= 0), then one code up when its value is
      // still below v: ceil((v - lo) / quantum) up to rounding, accepted when value() confirms it.
      const double t = (v - range_.lo) * inverse_;
      uint32_t q = t < double(q_max_) ? uint32_t(t) : q_max_;
      if (q < q_max_ && value(q) < v) ++q;
      if (value(q) >= v && (q == 0 || value(q - 1) < v)) return q;
    }
    return up_by_search(v);
  }
  uint32_t down(double v) const {
    const uint32_t u = up(v);
    return value(u) == v ? u : u - 1;
  }
  double quantum() const { return quantum_; }

 private:
  // Checks lo <= v <= hi (Error(runtime_failure) otherwise) and finds the code by binary search.
  uint32_t up_by_search(double v) const;
  RmqRange range_;
  uint32_t bits_, q_max_;
  double quantum_, inverse_;
  bool fast_;
};

}  // namespace mbk
