// Sample positions and interval slopes of the `lut` kind (see lut_layout.h).
#include "formats/lut_layout.h"

namespace mbk {

double lut_sample_position(double lo, double hi, uint32_t size, uint32_t j) {
  if (j + 1 >= size) return hi;
  return lo + (hi - lo) * (double(j) / double(size - 1));
}

double lut_interval_slope(double lo, double hi, uint32_t size, double v0, double v1) {
  if (!(hi > lo)) return 0.0;
  return (v1 - v0) / ((hi - lo) / double(size - 1));
}

}  // namespace mbk
