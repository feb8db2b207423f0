// The box-filtered MIP pyramid of a multi-channel float image, shared by the pyramids microbake bakes (normal pyramids,
// libbake/image/normal_pyramid.h; moment pyramids, libbake/colormap/moment_pyramid.h). Level sizes and coverage come
// from formats/mip_levels.h: level k texel (i, j) holds the area-weighted mean of the finest texels over its rectangle,
// accumulated in double from level 0 (so a level costs O(W H) and does not depend on the levels between), stored as
// float. Each texel is written by one iteration in a fixed order, so the result does not depend on the thread count.
// Lookups into any pyramid read through libbake/image/texture_taps.h.
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/image/image_io.h"

namespace mbk {

// levels[0] is `finest` itself; an empty vector for an empty image. Error(runtime_failure) when the pixel
// count does not match the size.
std::vector<Image> build_box_pyramid(const Image& finest);

}  // namespace mbk
