// MIP pyramids of normal maps and their bilinear/trilinear lookups (see normal_pyramid.h): the generic box
// pyramid (box_pyramid.h) and taps (texture_taps.h) applied to the three components.
#include "libbake/image/normal_pyramid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

#include "formats/error.h"
#include "libbake/image/box_pyramid.h"
#include "libbake/image/texture_taps.h"

namespace mbk {
namespace {

Vec3 texel(const NormalMap& level, uint32_t x, uint32_t row) { return level.at(x, row).cast<double>(); }

}  // namespace

NormalPyramid build_normal_pyramid(NormalMap map) {
  if (map.texels.size() != size_t(map.width) * map.height)
    throw Error(ExitCode::runtime_failure, "internal: normal map texel count does not match its size");
  NormalPyramid pyramid;
  if (map.texels.empty()) return pyramid;
  // Vec3f is three packed floats, so the texels are the finest image's 3-channel pixels as they are.
  static_assert(sizeof(Vec3f) == 3 * sizeof(float));
  const std::span<const float> finest(reinterpret_cast<const float*>(map.texels.data()), 3 * map.texels.size());
  std::vector<Image> coarser = build_coarser_levels(finest, map.width, map.height, 3);
  pyramid.levels.reserve(1 + coarser.size());
  pyramid.levels.push_back(std::move(map));
  for (Image& level : coarser) {
    NormalMap n;
    n.width = level.width;
    n.height = level.height;
    n.texels.resize(size_t(n.width) * n.height);
    std::copy(level.pixels.begin(), level.pixels.end(), reinterpret_cast<float*>(n.texels.data()));
    level = Image{};  // released as soon as it is copied
    pyramid.levels.push_back(std::move(n));
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
