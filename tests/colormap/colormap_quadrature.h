// An independent reference for prefiltered colour maps: E[C(m + sigma Z)], Z ~ N(0, 1), by numerical quadrature
// of the piecewise-linear, clamp-extended C (its own evaluator, not ColormapCurve's closed form), integrated piece by
// piece between the knots (C is linear on each piece) with 24-point Gauss-Legendre on sub-intervals of at most
// sigma / 4, over m +- 12 sigma (the tails beyond carry < 1e-32 of the mass).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "libbake/core/gauss_legendre.h"

namespace mbk::test {

struct PiecewiseLinearMap {
  std::vector<double> x;
  std::vector<std::array<double, 3>> c;
  // Clamped outside; right-continuous at repeated knots.
  std::array<double, 3> operator()(double v) const {
    if (v < x.front()) return c.front();
    size_t k = x.size() - 1;
    while (k > 0 && x[k] > v) --k;  // last knot at or below v (the later of a repeated pair)
    if (k + 1 == x.size()) return c.back();
    const double a = (v - x[k]) / (x[k + 1] - x[k]);
    return {c[k][0] + a * (c[k + 1][0] - c[k][0]), c[k][1] + a * (c[k + 1][1] - c[k][1]),
            c[k][2] + a * (c[k + 1][2] - c[k][2])};
  }
};

inline std::array<double, 3> gaussian_average_by_quadrature(const PiecewiseLinearMap& map, double m, double sigma) {
  if (sigma == 0.0) return map(m);
  static const std::vector<QuadratureNode> rule = gauss_legendre_nodes(24);  // tests/core/gauss_legendre_test.cpp
  const double lo = m - 12.0 * sigma, hi = m + 12.0 * sigma;
  std::vector<double> cuts = {lo, hi};
  for (double k : map.x)
    if (k > lo && k < hi) cuts.push_back(k);
  std::sort(cuts.begin(), cuts.end());
  std::array<double, 3> sum{0, 0, 0};
  for (size_t p = 0; p + 1 < cuts.size(); ++p) {
    const double a = cuts[p], b = cuts[p + 1];
    if (!(b > a)) continue;
    const int pieces = std::max(1, int(std::ceil((b - a) / (0.25 * sigma))));
    const double h = (b - a) / pieces;
    for (int q = 0; q < pieces; ++q) {
      const double mid = a + (q + 0.5) * h, half = 0.5 * h;
      for (const auto& [z, w] : rule) {
        // Interior points of (a, b) only, so a repeated knot at a or b does not matter.
        const double v = mid + half * z, t = (v - m) / sigma;
        const double weight = w * half * std::exp(-0.5 * t * t) / (sigma * std::sqrt(2.0 * M_PI));
        const auto cv = map(v);
        for (int c = 0; c < 3; ++c) sum[c] += weight * cv[c];
      }
    }
  }
  return sum;
}

}  // namespace mbk::test
