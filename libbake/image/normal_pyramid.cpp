// MIP pyramids of normal maps and their bilinear/trilinear lookups (see normal_pyramid.h; level sizes and
// coverage weights from formats/mip_levels.h).
//
// Every level is computed from level 0 directly, in double: texel (i, j) is the separable weighted sum
// sum_y wy (sum_x wx n(x, y)) over the finest texels its rectangle overlaps. The rectangles of a level
// tile the image, so a level costs O(W H) whatever its size; each texel is written by one iteration in a
// fixed order, so the result does not depend on the thread count.
#include "libbake/image/normal_pyramid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "formats/error.h"
#include "formats/mip_levels.h"
#include "libbake/core/parallel.h"
#include "libbake/image/texture_taps.h"

namespace mbk {
namespace {

Vec3 texel(const NormalMap& level, int64_t x, int64_t row) {
  return level.at(uint32_t(x), uint32_t(row)).cast<double>();
}

}  // namespace

NormalPyramid build_normal_pyramid(const NormalMap& map) {
  NormalPyramid pyramid;
  const auto sizes = mip_level_sizes(map.width, map.height);
  if (sizes.empty()) return pyramid;
  if (map.texels.size() != size_t(map.width) * map.height)
    throw Error(ExitCode::runtime_failure, "internal: normal map texel count does not match its size");
  pyramid.levels.push_back(map);
  for (size_t k = 1; k < sizes.size(); ++k) {
    const uint32_t w = sizes[k].width, h = sizes[k].height;
    const auto wx = mip_texel_weights(w, map.width), wy = mip_texel_weights(h, map.height);
    NormalMap level;
    level.width = w;
    level.height = h;
    level.texels.resize(size_t(w) * h);
    parallel_for(0, h, [&](int64_t row) {
      const uint32_t j = uint32_t(row);
      for (uint32_t i = 0; i < w; ++i) {
        Vec3 mean = Vec3::Zero();
        for (const MipWeight& y : wy[j]) {
          Vec3 along_x = Vec3::Zero();
          for (const MipWeight& x : wx[i]) along_x += x.weight * texel(map, x.index, y.index);
          mean += y.weight * along_x;
        }
        level.at(i, j) = mean.cast<float>();
      }
    });
    pyramid.levels.push_back(std::move(level));
  }
  return pyramid;
}

// Texel centres and wrapping: libbake/image/texture_taps.h.
Vec3 sample_bilinear(const NormalMap& level, const Vec2& uv) {
  if (level.width == 0 || level.height == 0)
    throw Error(ExitCode::runtime_failure, "internal: sampling an empty normal map");
  if (!std::isfinite(uv.x()) || !std::isfinite(uv.y())) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  Vec3 sum = Vec3::Zero();
  for (const TextureTap& tap : bilinear_taps(level.width, level.height, uv))
    sum += tap.weight * texel(level, tap.x, tap.row);
  return sum;
}

Vec3 sample_pyramid(const NormalPyramid& pyramid, const Vec2& uv, double lod) {
  if (pyramid.levels.empty()) throw Error(ExitCode::runtime_failure, "internal: sampling an empty pyramid");
  if (std::isnan(lod)) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const LevelBlend b = level_blend(pyramid.levels.size(), lod);
  const Vec3 fine = sample_bilinear(pyramid.levels[b.fine], uv);
  if (b.t == 0.0) return fine;
  return (1 - b.t) * fine + b.t * sample_bilinear(pyramid.levels[b.coarse], uv);
}

}  // namespace mbk
