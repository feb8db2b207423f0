// Hard cases of colour-map filtering ([Heitz13]; libbake/colormap/): a hard edge as sigma -> 0 against the closed
// form of a step convolved with a Gaussian, and the height- and slope-correlated colours at grazing angles
// (Lambda -> 20, the end of the range the height fit covers, and beyond) against the brute-force averages of
// libbake/colormap/colormap_reference.h over 40,000 stratified Gaussian samples.
// (sigma = 1e-300 and the edge's midpoint: ColormapTable.TinySigmaIsCWithoutUnderflow and
// HardEdgeAveragesItsTwoColoursAtTheEdge; a constant or 1 x 1 driver's zero variance:
// MomentPyramid.ConstantDriverHasZeroVarianceEverywhere and OneByOneHasZeroVariance.)
#include <gtest/gtest.h>

#include <cmath>

#include "libbake/colormap/colormap_reference.h"
#include "libbake/colormap/colormap_shading.h"
#include "libbake/glint/standard_normal.h"
#include "tests/colormap/test_table.h"

namespace mbk {
namespace {

// Stratified standard normal samples (quantiles at (i + 0.5) / n).
std::vector<double> normal_quantiles(int n) {
  std::vector<double> z;
  for (int i = 0; i < n; ++i) z.push_back(standard_normal_quantile((i + 0.5) / n));
  return z;
}

// The direction at azimuth phi whose Smith Lambda over isotropic slopes of variance v is `lambda` (bisection on
// the polar angle: Lambda grows monotonically towards the horizon).
Vec3 direction_with_lambda(double lambda, double phi, double v) {
  double lo = 0.0, hi = std::numbers::pi / 2;
  auto dir = [&](double t) { return Vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)); };
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (smith_lambda(dir(mid), Mat2::Identity() * v) < lambda ? lo : hi) = mid;
  }
  return dir(lo);
}

// Protects against: a hard edge (two knots at one position) turning into ringing or a NaN as sigma -> 0 (the
// Gaussian's argument (edge - m) / sigma grows without bound). A map constant A left of the edge and B right of it,
// clamp-extended, convolves to exactly A + (B - A) Phi((m - edge) / sigma) for every sigma.
TEST(HardCases, ColormapHardEdgeAsSigmaTendsToZero) {
  ColormapCurve c;
  c.knots = {0.2, 0.5, 0.5, 0.8};
  const std::array<double, 3> A{0.1, 0.7, 0.3}, B{0.9, 0.2, 0.05};
  c.colors = {A, A, B, B};
  for (const double sigma : {1e-2, 1e-6, 1e-12, 1e-200})
    for (double k = -6.0; k <= 6.0; k += 0.25) {
      const double m = 0.5 + k * sigma;  // rounded: (m - 0.5) / sigma is the k the map sees
      const auto v = c.convolved(m, sigma);
      const double phi = standard_normal_cdf((m - 0.5) / sigma);
      for (int ch = 0; ch < 3; ++ch)
        ASSERT_NEAR(v[ch], A[ch] + (B[ch] - A[ch]) * phi, 1e-11) << "sigma " << sigma << " k " << k;
    }
  // Through the table (one bilinear lookup), at sigma below its first row: every colour a convex combination of A
  // and B, monotone across the edge (no overshoot from interpolating the discontinuous sigma ~ 0 cells).
  const test::TestTable t = test::bake_test_table(c.knots, c.colors, 0.0, 1.0, 0.5);
  double previous = -1.0;
  for (double m = 0.45; m <= 0.55; m += 1e-4) {
    const Vec3 v = texture_colormap(t.baked.table, m, 1e-9, ColormapFiltering::texture);
    const double s = (v.x() - A[0]) / (B[0] - A[0]);
    ASSERT_GE(s, -1e-6) << m;
    ASSERT_LE(s, 1 + 1e-6) << m;
    for (int ch = 1; ch < 3; ++ch) ASSERT_NEAR(v[ch], A[ch] + (B[ch] - A[ch]) * s, 1e-6) << m;
    ASSERT_GE(s, previous - 1e-7) << m;
    previous = s;
  }
}

// Protects against: the height-correlated colour at grazing view and light, where Lambda -> 20 (89.7 degrees for
// slope deviation 0.3): V_bar and the shifted, narrowed height distribution of Eqs. 13-18 must match the brute force
// of Eq. 14 over the heights. Tolerance 0.02: the Gaussian stand-in for D_h and the refit's mean residual (0.043
// sigma_h at L <= 20) times the map's slope (height_filtering_test.cpp measures both). Beyond the fit's range
// (Lambda = 1000, 89.996 degrees) only V_bar (exact) and the colour range are asserted: the fitted mean keeps
// growing as log(L) while the exact one (the mean of the maximum of L + 1 Gaussians) grows as sqrt(2 log L), and
// the error against the brute force grows with it (measured 0.026 at L = 50, 0.056 at 200, 0.092 at 1000).
TEST(HardCases, ColormapHeightCorrelatedAtGrazingAngles) {
  const test::TestTable t = test::banded_unit_table();
  Microsurface s;
  s.sigma_h = 0.1, s.height_offset = 0.5;
  s.slopes.covariance = Mat2::Identity() * 0.09;
  std::vector<WeightedValue> heights;
  for (double z : normal_quantiles(40000)) heights.push_back({s.sigma_h * z, 1.0});
  for (const auto& [lambda_o, lambda_i, tolerance] :
       {std::tuple{20.0, 0.0, 0.02}, {10.0, 10.0, 0.02}, {0.0, 20.0, 0.02}, {1000.0, 3.0, 1.0}}) {
    const Vec3 wo = direction_with_lambda(lambda_o, 0.3, 0.09), wi = direction_with_lambda(lambda_i, 2.0, 0.09);
    const double lo = smith_lambda(wo, s.slopes.covariance), li = smith_lambda(wi, s.slopes.covariance);
    ASSERT_NEAR(lo, lambda_o, 1e-6 * lambda_o + 1e-9);
    const Vec3 reference = reference_height_colormap(t.baked.curve, heights, s.sigma_h, s.height_offset, lo, li);
    const HeightColormap filtered = height_colormap(t.baked.table, s, wo, wi, ColormapFiltering::filtered);
    ASSERT_TRUE(filtered.color.allFinite());
    EXPECT_NEAR(filtered.visibility, (1 + lo) / (1 + lo + li), 1e-12);
    EXPECT_LT((reference - filtered.color).cwiseAbs().maxCoeff(), tolerance) << lambda_o << " " << lambda_i;
    // A convex combination of the map's colours, times V_bar (the map's colours lie in [0.1, 1]).
    EXPECT_GE(filtered.color.minCoeff(), 0.1 * filtered.visibility - 1e-6);
    EXPECT_LE(filtered.color.maxCoeff(), filtered.visibility + 1e-6);
  }
}

// Protects against: the slope-correlated colour at grazing view (Lambda -> 20 and 1000), where the visible-slope
// distribution (w_z - s . w_xy)_+ p(s) is a thin sliver of the slope Gaussian: the moment-matched D_s must still
// give the brute-force colour of Eq. 19 over the slopes (a 200 x 200 stratified grid of the Gaussian).
TEST(HardCases, ColormapSlopeCorrelatedAtGrazingAngles) {
  const test::TestTable t = test::banded_unit_table();
  Microsurface s;
  s.slopes.mean = Vec2(0.05, -0.1);
  s.slopes.covariance = Mat2::Identity() * 0.09;
  const std::vector<double> z = normal_quantiles(200);
  std::vector<WeightedSlope> slopes;
  for (double a : z)
    for (double b : z) slopes.push_back({s.slopes.mean + 0.3 * Vec2(a, b), 1.0});
  const Vec2 direction = Vec2(1.0, 0.5).normalized();
  for (const double lambda : {20.0, 1000.0})
    for (const double phi : {0.0, 2.5}) {
      const Vec3 wo = direction_with_lambda(lambda, phi, 0.09);
      const Vec3 reference = reference_slope_colormap(t.baked.curve, slopes, direction, 0.5, wo);
      const Vec3 filtered = slope_colormap(t.baked.table, s, direction, 0.5, wo, ColormapFiltering::filtered);
      ASSERT_TRUE(filtered.allFinite());
      EXPECT_LT((reference - filtered).cwiseAbs().maxCoeff(), 0.02) << "Lambda " << lambda << " phi " << phi;
    }
}

}  // namespace
}  // namespace mbk
