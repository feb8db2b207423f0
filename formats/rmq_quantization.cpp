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
  return RmqQuantizer(range, bits).value(code);
}

uint32_t rmq_quantize_up(double v, const RmqRange& range, uint32_t bits) { return RmqQuantizer(range, bits).up(v); }

uint32_t rmq_quantize_down(double v, const RmqRange& range, uint32_t bits) { return RmqQuantizer(range, bits).down(v); }

uint32_t RmqQuantizer::up_by_search(double v) const {
  if (!(v >= range_.lo && v <= range_.hi))
    throw Error(ExitCode::runtime_failure, "internal: rmq value " + number_text(v) + " outside its range [" +
                                               number_text(range_.lo) + ", " + number_text(range_.hi) + "]");
  // Ranges so narrow that consecutive codes share a value, or an off guess: the smallest q with value(q) >= v;
  // value(q_max) = hi >= v, so it exists.
  uint32_t lo = 0, hi = q_max_;
  while (lo < hi) {
    const uint32_t mid = lo + (hi - lo) / 2;
    if (value(mid) >= v)
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

}  // namespace mbk
