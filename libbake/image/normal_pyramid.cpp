// MIP pyramids of normal maps and their bilinear/trilinear lookups (see normal_pyramid.h; level sizes and
// coverage from formats/mip_levels.h).
//
// Each level is built from the previous one's *sums* over finest texels, kept in double: a parent's sum is
// the plain sum of its children's sums, and its mean is that sum divided by the number of finest texels it
// covers (mip_coverage along x times along y). This is the exact coverage-weighted mean of the finest
// normals up to double rounding, whatever the sizes (odd, 1 x N), and only one double level is alive at a
// time (a quarter of the input's texels after the first step).
#include "libbake/image/normal_pyramid.h"

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
  const uint32_t W = map.width, H = map.height;
  // sums[k-1]: sum over the finest texels each texel of the previous level covers.
  std::vector<Vec3> previous(map.texels.size());
  for (size_t i = 0; i < map.texels.size(); ++i) previous[i] = map.texels[i].cast<double>();
  for (size_t k = 1; k < sizes.size(); ++k) {
    const uint32_t pw = sizes[k - 1].width, ph = sizes[k - 1].height;
    const uint32_t w = sizes[k].width, h = sizes[k].height;
    std::vector<Vec3> sums(size_t(w) * h);
    NormalMap level;
    level.width = w;
    level.height = h;
    level.texels.resize(sums.size());
    parallel_for(0, h, [&](int64_t row) {
      const uint32_t j = uint32_t(row);
      const double cover_y = mip_coverage(H, uint32_t(k), j);
      for (uint32_t i = 0; i < w; ++i) {
        Vec3 s = Vec3::Zero();
        for (uint32_t cy = 2 * j; cy < std::min(2 * j + 2, ph); ++cy)
          for (uint32_t cx = 2 * i; cx < std::min(2 * i + 2, pw); ++cx) s += previous[size_t(cy) * pw + cx];
        sums[size_t(j) * w + i] = s;
        level.at(i, j) = (s / (double(mip_coverage(W, uint32_t(k), i)) * cover_y)).cast<float>();
      }
    });
    pyramid.levels.push_back(std::move(level));
    previous = std::move(sums);
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
