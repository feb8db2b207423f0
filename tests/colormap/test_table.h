// A 512 x 256 prefiltered table of a given colour map over [lo, hi] x [0, sigma_max], with its independent
// quadrature reference (colormap_quadrature.h), for the tests of the filtering cases that read a table.
#pragma once

#include "libbake/colormap/colormap_table.h"
#include "tests/colormap/colormap_quadrature.h"

namespace mbk::test {

struct TestTable {
  BakedColormap baked;
  PiecewiseLinearMap reference;  // the stored C, for quadrature
};

inline TestTable bake_test_table(std::vector<double> knots, std::vector<std::array<double, 3>> colors, double lo,
                                 double hi, double sigma_max) {
  ColormapCurve c;
  c.knots = std::move(knots);
  c.colors = std::move(colors);
  ColormapTableOptions o;
  o.width = 512, o.height = 256, o.mean_min = lo, o.mean_max = hi, o.sigma_max = sigma_max;
  TestTable t{bake_colormap_table(c, o, Progress::silent()), {}};
  t.reference = {t.baked.curve.knots, t.baked.curve.colors};
  return t;
}

// A banded map over [0, 1] with a hard edge at 0.5 (the colour-map shading and reference tests).
inline TestTable banded_unit_table() {
  return bake_test_table(
      {0.1, 0.35, 0.5, 0.5, 0.7, 0.9},
      {{0.1, 0.2, 0.6}, {0.3, 0.7, 0.2}, {0.6, 0.6, 0.1}, {0.9, 0.2, 0.1}, {0.8, 0.8, 0.7}, {1, 1, 1}}, 0.0, 1.0, 0.5);
}

}  // namespace mbk::test
