// The sRGB transfer function (IEC 61966-2-1): decoding an sRGB-encoded value in [0, 1] to linear light. Colour
// maps given as 8/16-bit images or as sRGB colour stops are decoded with it before any filtering, because
// filtering averages light (linear values), not codes.
#pragma once

namespace mbk {

// Encoded -> linear: v / 12.92 up to 0.04045, ((v + 0.055) / 1.055)^2.4 above.
double srgb_to_linear(double encoded);

}  // namespace mbk
