// Builds SH NDF pyramids (see sh_pyramid.h).
#include "libbake/filter/sh_pyramid.h"

#include <algorithm>
#include <string>

#include "formats/error.h"
#include "formats/mip_levels.h"
#include "libbake/core/parallel.h"
#include "libbake/core/sh_basis.h"

namespace mbk {
namespace {

// Whether each texel of the level of `extent` texels covers exactly 1 or 2 whole texels of the level of
// `finer` texels (so its mean is the mean of those).
bool nests(uint32_t finer, uint32_t extent) { return finer == 2 * extent || (finer == 1 && extent == 1); }

// Level texels from the finest normals: texel (i, j) = sum over its x-list and y-list of wx wy Y(n(x, y)).
ShLevel level_from_normals(const NormalMap& map, const ShBasisEvaluator& basis, uint32_t w, uint32_t h) {
  const int count = basis.count();
  const auto wx = mip_texel_weights(w, map.width), wy = mip_texel_weights(h, map.height);
  // Per finest column, the level columns it falls in and its weight in each (the transpose of wx).
  std::vector<std::vector<std::pair<uint32_t, double>>> columns(map.width);
  for (uint32_t i = 0; i < w; ++i)
    for (const MipWeight& x : wx[i]) columns[x.index].push_back({i, x.weight});
  ShLevel level{w, h, std::vector<float>(size_t(w) * h * size_t(count))};
  parallel_for(0, h, [&](int64_t row) {
    std::vector<double> sum(size_t(w) * size_t(count), 0.0), y(static_cast<size_t>(count));
    for (const MipWeight& fy : wy[size_t(row)])
      for (uint32_t x = 0; x < map.width; ++x) {
        // Normalised in double: a float normal's length is 1 only to ~6e-8, and the basis takes cos(theta) = z,
        // whose error the Legendre recurrence multiplies by ~l^2 near the poles (test:
        // HardCases.ShOrder128NearThePoleFromFloatNormals).
        basis.evaluate(map.at(x, fy.index).cast<double>().normalized(), y);
        for (const auto& [i, weight] : columns[x]) {
          double* s = &sum[size_t(i) * size_t(count)];
          const double f = fy.weight * weight;
          for (int k = 0; k < count; ++k) s[k] += f * y[size_t(k)];
        }
      }
    for (size_t k = 0; k < sum.size(); ++k) level.coefficients[size_t(row) * w * size_t(count) + k] = float(sum[k]);
  });
  return level;
}

// Box mean of the 1 or 2 x 1 or 2 children of each texel (sizes nest: see nests()).
ShLevel level_from_children(const ShLevel& finer, int count, uint32_t w, uint32_t h) {
  const uint32_t sx = finer.width / w, sy = finer.height / h;  // 1 or 2
  ShLevel level{w, h, std::vector<float>(size_t(w) * h * size_t(count))};
  parallel_for(0, h, [&](int64_t row) {
    const uint32_t j = uint32_t(row);
    std::vector<double> sum(static_cast<size_t>(count));
    for (uint32_t i = 0; i < w; ++i) {
      // Coefficients innermost: each child's coefficients are read in order, once.
      std::fill(sum.begin(), sum.end(), 0.0);
      for (uint32_t dy = 0; dy < sy; ++dy)
        for (uint32_t dx = 0; dx < sx; ++dx) {
          const float* child = finer.texel(i * sx + dx, j * sy + dy, count);
          for (int k = 0; k < count; ++k) sum[size_t(k)] += child[k];
        }
      float* out = &level.coefficients[(size_t(j) * w + i) * size_t(count)];
      for (int k = 0; k < count; ++k) out[k] = float(sum[size_t(k)] / double(sx * sy));
    }
  });
  return level;
}

}  // namespace

ShPyramid build_sh_pyramid(const NormalMap& map, int order, Progress& progress) {
  const ShBasisEvaluator basis(order);
  ShPyramid pyramid;
  pyramid.order = order;
  const auto sizes = mip_level_sizes(map.width, map.height);
  progress.start("sh (levels)", sizes.empty() ? 0 : sizes.size() - 1);
  for (size_t k = 1; k < sizes.size(); ++k) {
    const uint32_t w = sizes[k].width, h = sizes[k].height;
    const bool from_children = k >= 2 && nests(sizes[k - 1].width, w) && nests(sizes[k - 1].height, h);
    pyramid.levels.push_back(from_children ? level_from_children(pyramid.levels.back(), basis.count(), w, h)
                                           : level_from_normals(map, basis, w, h));
    progress.advance();
  }
  progress.finish();
  return pyramid;
}

}  // namespace mbk
