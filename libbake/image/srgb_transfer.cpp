// The sRGB decoding curve (see srgb_transfer.h).
#include "libbake/image/srgb_transfer.h"

#include <cmath>

namespace mbk {

double srgb_to_linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

}  // namespace mbk
