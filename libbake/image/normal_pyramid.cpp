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

namespace mbk {
namespace {

// Wraps an integer texel index into [0, n).
int64_t wrap_index(int64_t i, int64_t n) {
  const int64_t m = i % n;
  return m < 0 ? m + n : m;
}

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

// Texel centres sit at integer + 0.5 in continuous texel coordinates (x right, row down), so the sample
// point in "centre" coordinates is (u W - 0.5, (1 - v) H - 0.5). Only the fractional part of uv matters
// (tiling); it is taken before scaling so that huge uv do not lose the texel index to rounding.
Vec3 sample_bilinear(const NormalMap& level, const Vec2& uv) {
  if (level.width == 0 || level.height == 0)
    throw Error(ExitCode::runtime_failure, "internal: sampling an empty normal map");
  if (!std::isfinite(uv.x()) || !std::isfinite(uv.y())) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const double u = uv.x() - std::floor(uv.x());
  const double t = (1.0 - uv.y()) - std::floor(1.0 - uv.y());  // row coordinate as a fraction of H
  const double fx = u * level.width - 0.5, fy = t * level.height - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const double ax = fx - x0, ay = fy - y0;
  const int64_t W = level.width, H = level.height;
  const int64_t xa = wrap_index(int64_t(x0), W), xb = wrap_index(int64_t(x0) + 1, W);
  const int64_t ya = wrap_index(int64_t(y0), H), yb = wrap_index(int64_t(y0) + 1, H);
  return (1 - ay) * ((1 - ax) * texel(level, xa, ya) + ax * texel(level, xb, ya)) +
         ay * ((1 - ax) * texel(level, xa, yb) + ax * texel(level, xb, yb));
}

Vec3 sample_pyramid(const NormalPyramid& pyramid, const Vec2& uv, double lod) {
  if (pyramid.levels.empty()) throw Error(ExitCode::runtime_failure, "internal: sampling an empty pyramid");
  if (std::isnan(lod)) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const double top = double(pyramid.levels.size() - 1);
  const double l = std::clamp(lod, 0.0, top);
  const size_t k0 = size_t(std::floor(l));
  const double a = l - double(k0);
  const Vec3 fine = sample_bilinear(pyramid.levels[k0], uv);
  if (a == 0.0) return fine;
  return (1 - a) * fine + a * sample_bilinear(pyramid.levels[k0 + 1], uv);
}

}  // namespace mbk
