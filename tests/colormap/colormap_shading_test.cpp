// Per-pixel colour-map filtering (libbake/colormap/colormap_shading.h): naive is the sigma = 0 row; head-on, the
// view-dependent height and slope filtering reduce to view-independent texture filtering; the height case with
// noise-perturbed heights matches quadrature of Eq. (14) with the noise convolved in; a light below the horizon
// gives black; the Sec. 6 combinations.
#include <gtest/gtest.h>

#include <cmath>

#include "libbake/colormap/colormap_shading.h"
#include "tests/colormap/test_table.h"

namespace mbk {
namespace {

test::TestTable table() { return test::banded_unit_table(); }

Microsurface surface() {
  Microsurface s;
  s.sigma_h = 0.08, s.height_offset = 0.5;
  s.slopes.mean = Vec2(0.05, -0.1);
  s.slopes.covariance << 0.09, 0.01, 0.01, 0.05;
  return s;
}

Vec3 direction(double degrees, double azimuth) {
  const double t = degrees * M_PI / 180;
  return Vec3(std::sin(t) * std::cos(azimuth), std::sin(t) * std::sin(azimuth), std::cos(t));
}

TEST(ColormapShading, NaiveIsTheSigmaZeroRowTextureTheLookup) {
  const auto t = table();
  const Vec3 naive = texture_colormap(t.baked.table, 0.52, 0.1, ColormapFiltering::naive);
  const Vec3 filtered = texture_colormap(t.baked.table, 0.52, 0.1, ColormapFiltering::texture);
  const auto exact_naive = t.baked.table.lookup(0.52, 0.0), exact = t.baked.table.lookup(0.52, 0.1);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(naive[c], exact_naive[c]);
    EXPECT_EQ(filtered[c], exact[c]);
  }
  EXPECT_GT((naive - filtered).norm(), 0.05);  // the hard edge at 0.5 is where naive filtering is wrong
}

TEST(ColormapShading, HeadOnHeightAndSlopeFilteringAreTextureFiltering) {
  const auto t = table();
  const Microsurface s = surface();
  const Vec3 up(0, 0, 1);
  const HeightColormap h = height_colormap(t.baked.table, s, up, up, ColormapFiltering::filtered);
  const HeightColormap ht = height_colormap(t.baked.table, s, up, up, ColormapFiltering::texture);
  EXPECT_EQ(h.visibility, 1.0);
  EXPECT_NEAR((h.color - ht.color).norm(), 0.0, 1e-12);
  const Vec2 d(0.6, 0.8);
  EXPECT_NEAR((slope_colormap(t.baked.table, s, d, 0.5, up, ColormapFiltering::filtered) -
               slope_colormap(t.baked.table, s, d, 0.5, up, ColormapFiltering::texture))
                  .norm(),
              0.0, 1e-12);
}

TEST(ColormapShading, HeightWithNoiseMatchesQuadratureOfEq14) {
  const auto t = table();
  const Microsurface s = surface();
  const double noise_mean = 0.03, noise_variance = 0.002;
  double worst = 0.0;
  for (double theta_o : {20.0, 70.0, 85.0})
    for (double theta_i : {0.0, 60.0, 80.0}) {
      const Vec3 wo = direction(theta_o, 0.4), wi = direction(theta_i, 2.9);
      const double lo = smith_lambda(wo, s.slopes.covariance), li = smith_lambda(wi, s.slopes.covariance);
      // V_bar int D_h(z) [C * N(0, noise_variance)](offset + noise_mean + sigma_h z) dz, D_h ~ Phi^L phi.
      double mass = 0.0;
      Vec3 sum = Vec3::Zero();
      for (int k = 0; k <= 4000; ++k) {
        const double z = -10 + 20.0 * k / 4000;
        const double w = std::pow(0.5 * std::erfc(-z / std::sqrt(2.0)), lo + li) * std::exp(-0.5 * z * z);
        const auto c = t.baked.curve.convolved(s.height_offset + noise_mean + s.sigma_h * z, std::sqrt(noise_variance));
        mass += w;
        sum += w * Vec3(c[0], c[1], c[2]);
      }
      const Vec3 exact = averaged_visibility(lo, li) * sum / mass;
      const HeightColormap h =
          height_colormap(t.baked.table, s, wo, wi, ColormapFiltering::filtered, noise_mean, noise_variance);
      EXPECT_NEAR(h.visibility, (1 + lo) / (1 + lo + li), 1e-15);
      worst = std::max(worst, (h.color - exact).cwiseAbs().maxCoeff());
    }
  EXPECT_LT(worst, 0.02);
}

TEST(ColormapShading, LightBelowTheHorizonIsBlack) {
  const auto t = table();
  const HeightColormap h =
      height_colormap(t.baked.table, surface(), direction(30, 0), Vec3(0.6, 0, -0.8), ColormapFiltering::filtered);
  EXPECT_EQ(h.visibility, 0.0);
  EXPECT_EQ(h.color, Vec3::Zero());
}

TEST(ColormapShading, Section6Combinations) {
  ColormapTerms t;
  t.c0 = Vec3(0.2, 0.4, 0.6), t.ch = Vec3(0.5, 0.5, 0.25), t.cs = Vec3(1.0, 0.5, 0.0), t.visibility = 0.8;
  ColormapWeights linear;
  linear.k0 = 0.5, linear.k1 = 0.25, linear.k2 = 0.25;
  EXPECT_NEAR((combine_colormaps(t, linear) - (0.5 * 0.8 * t.c0 + 0.25 * t.ch + 0.25 * 0.8 * t.cs)).norm(), 0, 1e-15);
  ColormapWeights product;
  product.product = true;
  EXPECT_NEAR((combine_colormaps(t, product) - Vec3(0.1, 0.1, 0.0)).norm(), 0, 1e-15);
}

}  // namespace
}  // namespace mbk
