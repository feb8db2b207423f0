// Grid positions of the `lut` kind (see lut_layout.h).
#include "formats/lut_layout.h"

namespace mbk {

double lut_sample_position(double lo, double hi, uint32_t size, uint32_t j) {
  if (j + 1 >= size) return hi;
  return lo + (hi - lo) * (double(j) / double(size - 1));
}

}  // namespace mbk
