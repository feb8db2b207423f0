// Box-filtered MIP pyramids (see box_pyramid.h).
#include "libbake/image/box_pyramid.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"
#include "formats/mip_levels.h"
#include "libbake/core/parallel.h"

namespace mbk {

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

}  // namespace mbk
