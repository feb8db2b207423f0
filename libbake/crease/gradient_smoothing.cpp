// Constrained Laplacian smoothing of the gradient map (see gradient_smoothing.h).
#include "libbake/crease/gradient_smoothing.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "libbake/core/parallel.h"

namespace mbk {

double smooth_gradient(CreaseField& field, uint32_t iterations) {
  const int64_t nx = field.samples_x(), ny = field.samples_y();
  const std::vector<float> original = field.gradient;
  std::vector<float> next(field.gradient.size());
  for (uint32_t it = 0; it < iterations; ++it) {
    const std::vector<float>& g = field.gradient;
    parallel_for(0, ny, [&](int64_t j) {
      for (int64_t i = 0; i < nx; ++i) {
        const size_t k = size_t(j * nx + i);
        double sx = 0.0, sy = 0.0;
        int n = 0;
        auto add = [&](int64_t ni, int64_t nj, float crossing) {
          if (crossing != kCreaseNoCrossing) return;
          const size_t m = size_t(nj * nx + ni);
          sx += g[2 * m];
          sy += g[2 * m + 1];
          ++n;
        };
        if (i > 0) add(i - 1, j, field.crossing_h[field.h_edge_index(uint32_t(i - 1), uint32_t(j))]);
        if (i + 1 < nx) add(i + 1, j, field.crossing_h[field.h_edge_index(uint32_t(i), uint32_t(j))]);
        if (j > 0) add(i, j - 1, field.crossing_v[field.v_edge_index(uint32_t(i), uint32_t(j - 1))]);
        if (j + 1 < ny) add(i, j + 1, field.crossing_v[field.v_edge_index(uint32_t(i), uint32_t(j))]);
        double gx = g[2 * k], gy = g[2 * k + 1];
        if (n > 0) {
          const double mx = gx + 0.5 * (sx / n - gx), my = gy + 0.5 * (sy / n - gy);
          const double len = std::sqrt(mx * mx + my * my);  // unit-scale components: no hypot needed
          if (len > 1e-12) gx = mx / len, gy = my / len;
        }
        next[2 * k] = float(gx);
        next[2 * k + 1] = float(gy);
      }
    });
    field.gradient.swap(next);
  }
  // The largest turn, per row in parallel, then over rows (a maximum: the same whatever the order).
  std::vector<double> row_worst(size_t(ny), 0.0);
  parallel_for(0, ny, [&](int64_t j) {
    for (size_t k = size_t(2 * j * nx); k < size_t(2 * (j + 1) * nx); k += 2) {
      const double dot = double(original[k]) * field.gradient[k] + double(original[k + 1]) * field.gradient[k + 1];
      row_worst[size_t(j)] = std::max(row_worst[size_t(j)], std::acos(std::clamp(dot, -1.0, 1.0)));
    }
  });
  return *std::max_element(row_worst.begin(), row_worst.end());
}

}  // namespace mbk
