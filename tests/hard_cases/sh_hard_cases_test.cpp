// Hard cases of the SH NDF pyramid at order 128 ([Han07] Sec. 7.4.1; libbake/filter/sh_pyramid.h): float normals
// a little off the pole and on the equator, checked against std::sph_legendre (tests/hard_cases/hard_case_checks.h)
// at the exact direction of the stored normal. (The basis itself at the exact poles and equator to order 128:
// ShBasis.FiniteAndExactAtPolesAndEquatorToOrder128.)
#include <gtest/gtest.h>

#include <cmath>

#include "libbake/core/sh_basis.h"
#include "libbake/filter/sh_pyramid.h"
#include "tests/hard_cases/hard_case_checks.h"

namespace mbk {
namespace {

// The float normal of a direction (its length rounded, as a loaded normal map holds it).
Vec3f float_normal(double x, double y, double z) { return Vec3(x, y, z).normalized().cast<float>(); }

// The largest error of level 1 of a 2 x 2 map of four copies of n (so level 1 is the basis at n's direction) in
// units of the f32 tolerance `validate` uses for sh assets (1e-6 |v| + 2e-6; float storage alone costs 6e-8 |v|).
double worst_error_in_tolerances(const Vec3f& n, int order) {
  NormalMap map;
  map.width = map.height = 2;
  map.texels.assign(4, n);
  const ShPyramid p = build_sh_pyramid(map, order, Progress::silent());
  const float* g = p.levels[0].texel(0, 0, sh_count(order));
  double worst = 0.0;
  for (int l = 0; l <= order; ++l)
    for (int m = -l; m <= l; ++m) {
      const double exact = test::independent_sh(l, m, n.cast<double>());
      worst = std::max(worst, std::abs(g[sh_index(l, m)] - exact) / (1e-6 * std::abs(exact) + 2e-6));
    }
  return worst;
}

// Protects against: cos(theta) taken from a float normal whose length is not exactly 1 (|n| - 1 up to 6e-8). Near
// the pole dY_l0 / dcos(theta) grows as l^2, so the length error alone put Y_16,0 6e-6 off (`sh --precision f32`;
// f16's coarser tolerance hid it) and these three normals 82x, 55x and 16x the f32 tolerance off at order 128.
// Fixed: the pyramid normalises each normal in double before the basis.
TEST(HardCases, ShOrder128NearThePoleFromFloatNormals) {
  for (const Vec3f& n :
       {float_normal(0.01, 0.02, 1.0), float_normal(-3e-4, 1e-4, 1.0), float_normal(0.05, -0.07, -1.0)}) {
    SCOPED_TRACE(std::abs(n.cast<double>().norm() - 1.0));
    EXPECT_LE(worst_error_in_tolerances(n, 128), 1.0);
  }
}

// Protects against: the sectoral terms at theta = pi / 2 (sin(theta)^m largest, every |Y_mm| at its bound) and
// float normals on the equator whose z is a rounding residue (1e-7), at order 128.
TEST(HardCases, ShOrder128OnTheEquator) {
  for (const Vec3f& n : {float_normal(1, 0, 0), float_normal(0.6, -0.8, 0.0), float_normal(1.0, 1.0, 1e-7)})
    EXPECT_LE(worst_error_in_tolerances(n, 128), 1.0);
}

}  // namespace
}  // namespace mbk
