// MIP pyramids of normal maps and their bilinear/trilinear lookups (see normal_pyramid.h): the generic box
// pyramid and taps of box_pyramid.h applied to the three components.
#include "libbake/image/normal_pyramid.h"

#include <cmath>
#include <limits>

#include "formats/error.h"
#include "libbake/image/box_pyramid.h"

namespace mbk {
namespace {

Vec3 texel(const NormalMap& level, uint32_t x, uint32_t row) { return level.at(x, row).cast<double>(); }

}  // namespace

NormalPyramid build_normal_pyramid(const NormalMap& map) {
  if (map.texels.size() != size_t(map.width) * map.height)
    throw Error(ExitCode::runtime_failure, "internal: normal map texel count does not match its size");
  Image finest;
  finest.width = map.width;
  finest.height = map.height;
  finest.channels = 3;
  finest.pixels.resize(map.texels.size() * 3);
  for (size_t i = 0; i < map.texels.size(); ++i)
    for (int c = 0; c < 3; ++c) finest.pixels[3 * i + size_t(c)] = map.texels[i][c];
  NormalPyramid pyramid;
  for (const Image& level : build_box_pyramid(finest)) {
    NormalMap n;
    n.width = level.width;
    n.height = level.height;
    n.texels.resize(size_t(n.width) * n.height);
    for (size_t i = 0; i < n.texels.size(); ++i)
      n.texels[i] = Vec3f(level.pixels[3 * i], level.pixels[3 * i + 1], level.pixels[3 * i + 2]);
    pyramid.levels.push_back(std::move(n));
  }
  return pyramid;
}

Vec3 sample_bilinear(const NormalMap& level, const Vec2& uv) {
  if (level.width == 0 || level.height == 0)
    throw Error(ExitCode::runtime_failure, "internal: sampling an empty normal map");
  if (!std::isfinite(uv.x()) || !std::isfinite(uv.y())) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const BilinearTaps t = bilinear_taps(uv, level.width, level.height);
  return (1 - t.ay) * ((1 - t.ax) * texel(level, t.x0, t.y0) + t.ax * texel(level, t.x1, t.y0)) +
         t.ay * ((1 - t.ax) * texel(level, t.x0, t.y1) + t.ax * texel(level, t.x1, t.y1));
}

Vec3 sample_pyramid(const NormalPyramid& pyramid, const Vec2& uv, double lod) {
  if (pyramid.levels.empty()) throw Error(ExitCode::runtime_failure, "internal: sampling an empty pyramid");
  if (std::isnan(lod)) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const LevelBlend b = level_blend(lod, pyramid.levels.size());
  const Vec3 fine = sample_bilinear(pyramid.levels[b.k0], uv);
  if (b.a == 0.0) return fine;
  return (1 - b.a) * fine + b.a * sample_bilinear(pyramid.levels[b.k0 + 1], uv);
}

}  // namespace mbk
