// The layout of asset kind 8, `moments` ([Heitz13] Sec. 4.2: the first two moments of a tabulated driver f at each
// level of detail; formats/SPEC.md "Kind 8: moments"), shared by the baker (libbake/colormap/moment_pyramid.h) and
// `validate` (formats/kind_moments.cpp).
//
// Sections level_0 .. level_{L-1}, each f32 [h_k, w_k, 2], sizes and texel coverage of formats/mip_levels.h. To keep
// the variance E[f^2] - E[f]^2 well conditioned in float, the moments are taken about a shift s (parameters.shift,
// the driver's mean rounded to float): level 0 texel = (d, d^2) with d = float(f - s) and d^2 = float(d * d); level k
// texel = the area-weighted mean of level 0 over its rectangle (accumulated in double). A footprint's mean is
// s + E[d] and its variance E[d^2] - E[d]^2 (a shift does not change it), after interpolating both moments.
#pragma once

#include <cstdint>
#include <string>

namespace mbk {

inline constexpr uint32_t kMomentsKindId = 8;
inline constexpr uint32_t kMomentsChannels = 2;

inline std::string moments_level_name(size_t k) { return "level_" + std::to_string(k); }

}  // namespace mbk
