// The box-filtered MIP pyramid of a multi-channel float image, and the wrapping bilinear taps of a lookup, shared
// by every pyramid microbake bakes (normal pyramids, libbake/image/normal_pyramid.h; moment pyramids,
// libbake/colormap/moment_pyramid.h). Level sizes and coverage come from formats/mip_levels.h: level k texel
// (i, j) holds the area-weighted mean of the finest texels over its rectangle, accumulated in double from level 0
// (so a level costs O(W H) and does not depend on the levels between), stored as float. Each texel is written by
// one iteration in a fixed order, so the result does not depend on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/image/image_io.h"

namespace mbk {

// levels[0] is `finest` itself; an empty vector for an empty image. Error(runtime_failure) when the pixel
// count does not match the size.
std::vector<Image> build_box_pyramid(const Image& finest);

// The four texels a bilinear lookup at uv reads in a width x height level, wrapping at the borders (tiling), in
// the conventions of normal_map.h (texel centres at ((x + 0.5) / W, 1 - (row + 0.5) / H)); the value is
// (1 - ay) ((1 - ax) t(x0, y0) + ax t(x1, y0)) + ay ((1 - ax) t(x0, y1) + ax t(x1, y1)). Only the fractional part
// of uv matters; it is taken before scaling so that huge uv keep their texel index. uv must be finite.
struct BilinearTaps {
  uint32_t x0, x1, y0, y1;  // columns and rows
  double ax, ay;
};
BilinearTaps bilinear_taps(const Vec2& uv, uint32_t width, uint32_t height);

// The two levels a trilinear lookup at `lod` blends: lod clamped to [0, levels - 1], level k0 with weight 1 - a
// and k0 + 1 with weight a (a == 0 at the last level). lod must not be NaN.
struct LevelBlend {
  size_t k0;
  double a;
};
LevelBlend level_blend(double lod, size_t levels);

}  // namespace mbk
