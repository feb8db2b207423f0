// Box-filtered MIP pyramids and bilinear taps (see box_pyramid.h).
#include "libbake/image/box_pyramid.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"
#include "formats/mip_levels.h"
#include "libbake/core/parallel.h"

namespace mbk {
namespace {

// Wraps an integer texel index into [0, n).
uint32_t wrap_index(int64_t i, int64_t n) {
  const int64_t m = i % n;
  return uint32_t(m < 0 ? m + n : m);
}

}  // namespace

std::vector<Image> build_box_pyramid(const Image& finest) {
  std::vector<Image> pyramid;
  const auto sizes = mip_level_sizes(finest.width, finest.height);
  if (sizes.empty()) return pyramid;
  const uint32_t C = finest.channels;
  if (C == 0 || finest.pixels.size() != size_t(finest.width) * finest.height * C)
    throw Error(ExitCode::runtime_failure, "internal: image pixel count does not match its size");
  pyramid.push_back(finest);
  for (size_t k = 1; k < sizes.size(); ++k) {
    Image level;
    level.width = sizes[k].width;
    level.height = sizes[k].height;
    level.channels = C;
    level.pixels.resize(size_t(level.width) * level.height * C);
    const auto wx = mip_texel_weights(level.width, finest.width), wy = mip_texel_weights(level.height, finest.height);
    parallel_for(0, level.height, [&](int64_t row) {
      const uint32_t j = uint32_t(row);
      std::vector<double> mean(C), along_x(C);
      for (uint32_t i = 0; i < level.width; ++i) {
        std::fill(mean.begin(), mean.end(), 0.0);
        for (const MipWeight& y : wy[j]) {
          std::fill(along_x.begin(), along_x.end(), 0.0);
          for (const MipWeight& x : wx[i])
            for (uint32_t c = 0; c < C; ++c) along_x[c] += x.weight * double(finest.at(x.index, y.index, c));
          for (uint32_t c = 0; c < C; ++c) mean[c] += y.weight * along_x[c];
        }
        for (uint32_t c = 0; c < C; ++c) level.at(i, j, c) = float(mean[c]);
      }
    });
    pyramid.push_back(std::move(level));
  }
  return pyramid;
}

// Texel centres sit at integer + 0.5 in continuous texel coordinates (x right, row down), so the sample
// point in "centre" coordinates is (u W - 0.5, (1 - v) H - 0.5).
BilinearTaps bilinear_taps(const Vec2& uv, uint32_t width, uint32_t height) {
  const double u = uv.x() - std::floor(uv.x());
  const double t = (1.0 - uv.y()) - std::floor(1.0 - uv.y());  // row coordinate as a fraction of H
  const double fx = u * width - 0.5, fy = t * height - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  return {wrap_index(int64_t(x0), width),
          wrap_index(int64_t(x0) + 1, width),
          wrap_index(int64_t(y0), height),
          wrap_index(int64_t(y0) + 1, height),
          fx - x0,
          fy - y0};
}

LevelBlend level_blend(double lod, size_t levels) {
  const double l = std::clamp(lod, 0.0, double(levels - 1));
  const size_t k0 = size_t(std::floor(l));
  return {k0, l - double(k0)};
}

}  // namespace mbk
