// The view-dependent slope filtering distribution (libbake/colormap/slope_filtering.h, [Heitz13] Sec. 5.2): the
// closed-form moments of D_s(s) ~ p(s) (w_z - s . w_xy)_+ against brute-force 2-D integration from head-on to
// 89.9 degrees, with a tilted mean slope and an anisotropic, correlated covariance; the far-back-facing series
// branch against the closed form where both hold; and the filtered colour C(d . s) through one table lookup against
// 2-D integration.
#include <gtest/gtest.h>

#include <cmath>

#include "libbake/colormap/colormap_table.h"
#include "libbake/colormap/slope_filtering.h"
#include "tests/colormap/test_table.h"

namespace mbk {
namespace {

SlopeGaussian tilted_anisotropic() {
  SlopeGaussian g;
  g.mean = Vec2(0.1, -0.05);
  g.covariance << 0.09, 0.02, 0.02, 0.04;
  return g;
}

Vec3 direction(double degrees, double azimuth) {
  const double t = degrees * M_PI / 180;
  return Vec3(std::sin(t) * std::cos(azimuth), std::sin(t) * std::sin(azimuth), std::cos(t));
}

// Brute force over an N x N midpoint grid covering +-10 standard deviations per axis.
struct BruteForce {
  double area = 0.0;
  Vec2 mean = Vec2::Zero();
  Mat2 covariance = Mat2::Zero();
  std::array<double, 3> color{0, 0, 0};
};
BruteForce brute_force(const SlopeGaussian& g, const Vec3& wo, const test::PiecewiseLinearMap* map = nullptr,
                       Vec2 d = Vec2::Zero(), int N = 1200) {
  const Mat2 inv = g.covariance.inverse();
  const double norm = 1.0 / (2 * M_PI * std::sqrt(g.covariance.determinant()));
  const double sx = std::sqrt(g.covariance(0, 0)), sy = std::sqrt(g.covariance(1, 1));
  const double hx = 20 * sx / N, hy = 20 * sy / N;
  BruteForce b;
  double mass = 0.0;
  Vec2 first = Vec2::Zero();
  Mat2 second = Mat2::Zero();
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      const Vec2 s(g.mean.x() - 10 * sx + (i + 0.5) * hx, g.mean.y() - 10 * sy + (j + 0.5) * hy);
      const Vec2 e = s - g.mean;
      const double w =
          norm * std::exp(-0.5 * e.dot(inv * e)) * std::max(0.0, wo.z() - s.x() * wo.x() - s.y() * wo.y()) * hx * hy;
      mass += w;
      first += w * s;
      second += w * s * s.transpose();
      if (map) {
        const auto c = (*map)(d.dot(s));
        for (int k = 0; k < 3; ++k) b.color[k] += w * c[k];
      }
    }
  b.area = mass;
  b.mean = first / mass;
  b.covariance = second / mass - b.mean * b.mean.transpose();
  for (double& c : b.color) c /= mass;
  return b;
}

TEST(SlopeFiltering, MomentsMatchBruteForce_HeadOnToGrazing) {
  const SlopeGaussian g = tilted_anisotropic();
  for (double deg : {0.0, 30.0, 60.0, 80.0, 89.0, 89.9})
    for (double azimuth : {0.3, 2.5}) {
      const Vec3 wo = direction(deg, azimuth);
      const VisibleSlopes v = visible_slope_distribution(g, wo);
      const BruteForce b = brute_force(g, wo);
      EXPECT_NEAR(v.projected_area, b.area, 1e-6 * b.area + 1e-9) << deg;
      EXPECT_NEAR((v.gaussian.mean - b.mean).norm(), 0.0, 1e-5) << deg << " " << azimuth;
      EXPECT_NEAR((v.gaussian.covariance - b.covariance).norm(), 0.0, 1e-5) << deg << " " << azimuth;
    }
}

TEST(SlopeFiltering, HeadOnLeavesTheSlopesUnchanged) {
  const SlopeGaussian g = tilted_anisotropic();
  const VisibleSlopes v = visible_slope_distribution(g, Vec3(0, 0, 1));
  EXPECT_EQ(v.gaussian.mean, g.mean);
  EXPECT_EQ(v.gaussian.covariance, g.covariance);
  EXPECT_EQ(v.projected_area, 1.0);
}

TEST(SlopeFiltering, GrazingShiftsTowardFacetsFacingTheViewer) {
  // Seen from +x, facets facing +x have n_x > 0, i.e. slope s_x < 0: the mean moves to negative s_x.
  SlopeGaussian g;
  g.covariance = Mat2::Identity() * 0.04;
  const VisibleSlopes v = visible_slope_distribution(g, direction(85.0, 0.0));
  EXPECT_LT(v.gaussian.mean.x(), -0.1);
  EXPECT_NEAR(v.gaussian.mean.y(), 0.0, 1e-15);
  EXPECT_LT(v.gaussian.covariance(0, 0), 0.04);           // squeezed along the view azimuth
  EXPECT_NEAR(v.gaussian.covariance(1, 1), 0.04, 1e-15);  // untouched across it
}

TEST(SlopeFiltering, NearHeadOnTinyVarianceAlongViewStaysFinite_LargeK) {
  // k = (w_z + m) / sqrt(v) ~ 40: phi(k) underflows. For large k the weight is ~ the ramp a + t, whose tilt
  // moves the mean by Sigma b / (a + m) and squeezes the variance along b by (Sigma b)(Sigma b)^T / (a + m)^2.
  SlopeGaussian g;
  g.covariance = Mat2::Identity() * 0.35 * 0.35;
  for (const Vec3& w : {Vec3(0.0142428, -0.0699566, 0.997448).normalized(), Vec3(1e-4, 0, 1).normalized()}) {
    const VisibleSlopes v = visible_slope_distribution(g, w);
    const Vec2 b(-w.x(), -w.y()), sb = g.covariance * b;
    ASSERT_TRUE(v.gaussian.mean.allFinite() && v.gaussian.covariance.allFinite() && std::isfinite(v.projected_area));
    EXPECT_LT((v.gaussian.mean - sb / w.z()).norm(), 1e-6);
    EXPECT_LT((v.gaussian.covariance - (g.covariance - sb * sb.transpose() / (w.z() * w.z()))).norm(), 1e-6);
    EXPECT_NEAR(v.projected_area, w.z(), 1e-12);
  }
}

TEST(SlopeFiltering, FarBackFacingMeanStaysFinite_SeriesBranch) {
  // A mean slope tilted 30+ standard deviations away from the viewer: k << -10, the series branch. Continuity
  // across the branch point (k = -10) and agreement with brute force where the mass is still representable.
  SlopeGaussian g;
  g.covariance = Mat2::Identity() * 0.0004;
  const Vec3 wo = direction(80.0, 0.0);
  double previous_mean = 0.0;
  for (double tilt : {5.0, 5.5, 5.6, 5.65, 5.7, 6.0, 8.0}) {
    g.mean = Vec2(tilt, 0.0);  // w_z - s_x w_x < 0 once s_x > cot(80 deg) = 0.176... far beyond
    const VisibleSlopes v = visible_slope_distribution(g, wo);
    ASSERT_TRUE(v.gaussian.mean.allFinite() && v.gaussian.covariance.allFinite()) << tilt;
    EXPECT_GE(v.gaussian.covariance(0, 0), 0.0);
    EXPECT_LT(v.gaussian.mean.x(), 0.1763 + 1e-9);  // visible facets are those facing the viewer
    if (tilt > 5.0) {
      EXPECT_LT(std::abs(v.gaussian.mean.x() - previous_mean), 0.05);
    }
    previous_mean = v.gaussian.mean.x();
  }
  // Near the branch point, both forms and the brute force agree.
  g.covariance = Mat2::Identity() * 0.01;
  for (double k : {-9.9, -10.1}) {
    // Choose the mean so that (a + m) / sqrt(v) = k with b = -w_xy.
    const double a = wo.z(), bx = -wo.x(), sd = std::abs(bx) * 0.1;
    g.mean = Vec2((k * sd - a) / bx, 0.0);
    const VisibleSlopes v = visible_slope_distribution(g, wo);
    const double cutoff = a / wo.x();  // facets with s_x below this face the viewer
    // Weighted by (cutoff - s_x)_+ the distribution concentrates just below the cutoff: mean ~ cutoff - 2 sd_s / |k|.
    EXPECT_NEAR(v.gaussian.mean.x(), cutoff - 2 * 0.1 / std::abs(k), 0.01 * 0.1) << k;
  }
}

TEST(SlopeFiltering, FilteredColorThroughOneLookupMatchesBruteForce) {
  const test::TestTable t = test::bake_test_table(
      {-0.6, -0.2, 0.0, 0.0, 0.3, 0.7},
      {{0.05, 0.1, 0.6}, {0.2, 0.6, 0.2}, {0.5, 0.5, 0.1}, {0.9, 0.3, 0.1}, {0.8, 0.8, 0.2}, {1, 1, 1}}, -1.0, 1.0,
      0.6);
  const SlopeGaussian g = tilted_anisotropic();
  const Vec2 d = Vec2(1.0, 0.5).normalized();
  double worst = 0.0;
  for (double deg : {0.0, 45.0, 75.0, 85.0, 89.5})
    for (double azimuth : {0.0, 1.2, M_PI}) {
      const Vec3 wo = direction(deg, azimuth);
      const DriverStatistics s = slope_driver(visible_slope_distribution(g, wo).gaussian, d);
      const auto looked_up = t.baked.table.lookup(s.mean, s.stddev);
      const BruteForce b = brute_force(g, wo, &t.reference, d, 600);
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(looked_up[k] - b.color[k]));
    }
  // The Gaussian stand-in for the ramp-tilted D_s costs at most this much colour (of a map in [0, 1]).
  EXPECT_LT(worst, 0.02);
  RecordProperty("worst_color_error", std::to_string(worst));
}

}  // namespace
}  // namespace mbk
