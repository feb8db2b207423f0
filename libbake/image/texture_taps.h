// Where a bilinear, box or trilinear texture lookup reads, independently of what the texels hold: the four texels
// and weights of a bilinear lookup (texel centres at integer + 0.5, wrapping at the borders, uv in the
// conventions of normal_map.h), the texels an axis-aligned box covers weighted by their overlap, and the two MIP
// levels and blend of a trilinear one. Every pyramid lookup
// (normal MIP maps, SH NDF pyramids, vMF mixture maps) uses these, so all filter the same way.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "libbake/core/eigen.h"

namespace mbk {

struct TextureTap {
  uint32_t x, row;
  double weight;  // the four weights sum to 1
};

// Texel coordinates of uv (x right, y = row down, the map [0, W] x [0, H]; texel centres at integer + 0.5):
// (frac(u) W, frac(1 - v) H). Only the fractional part of uv matters (tiling).
Vec2 texel_coordinates(const Vec2& uv, uint32_t width, uint32_t height);

// The sample point in "centre" coordinates is (u W - 0.5, (1 - v) H - 0.5); only the fractional part of uv
// matters (tiling), taken before scaling so that huge uv keep their texel index. uv must be finite, the size
// non-zero (callers check).
std::array<TextureTap, 4> bilinear_taps(uint32_t width, uint32_t height, const Vec2& uv);

// The texels of a width x height level that the box centred at uv, of half widths (half_x, half_y) in that
// level's texels, overlaps, each weighted by its overlap area over the box's (the weights sum to 1). A box that
// wraps onto a texel more than once gives it one tap with the summed overlap, so there are at most
// min(width, 2 half_x + 2) x min(height, 2 half_y + 2) taps. Empty when a half width is not finite and > 0.
std::vector<TextureTap> box_taps(uint32_t width, uint32_t height, const Vec2& uv, double half_x, double half_y);

struct LevelBlend {
  size_t fine, coarse;  // levels to read (coarse == fine when the blend is 0)
  double t;             // weight of the coarse level, in [0, 1)
};
// lod clamped to [0, levels - 1] (lod must not be NaN; levels >= 1).
LevelBlend level_blend(size_t levels, double lod);

}  // namespace mbk
