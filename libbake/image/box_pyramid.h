// The box-filtered MIP pyramid of a multi-channel float image, shared by the pyramids microbake bakes (normal pyramids,
// libbake/image/normal_pyramid.h; moment pyramids, libbake/colormap/moment_pyramid.h). Level sizes and coverage come
// from formats/mip_levels.h: level k texel (i, j) holds the area-weighted mean of the finest texels over its rectangle,
// accumulated in double from level 0 (so a level does not depend on the levels between), stored as float. The sum's
// order is fixed: per finest row of the rectangle, in order, the row's weighted texels are summed left to right, and
// each row's sum, times its weight, is added to the texel's. Each texel is written by one iteration, so the result does
// not depend on the thread count. Lookups into any pyramid read through libbake/image/texture_taps.h.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/image/image_io.h"

namespace mbk {

// Levels 1, 2, ... (every level but the finest) of the pyramid of a width x height image of `channels` interleaved
// floats per texel, row-major; empty for a one-texel or empty image. Error(runtime_failure) when the float count does
// not match the size.
std::vector<Image> build_coarser_levels(std::span<const float> finest, uint32_t width, uint32_t height,
                                        uint32_t channels);

// levels[0] is `finest` itself (moved in), then build_coarser_levels; an empty vector for an empty image.
std::vector<Image> build_box_pyramid(Image finest);

}  // namespace mbk
