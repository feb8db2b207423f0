// The brute-force references (libbake/colormap/colormap_reference.h) against the filtered evaluations they judge:
// with samples that follow the model's Gaussian statistics exactly (stratified normal quantiles), the texture
// reference converges to the table lookup, the height reference to V_bar <C, D_h> of Eq. (14), the slope reference
// to the moment-matched Cs_bar; and the degenerate cases (no samples, light below the horizon) are black.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "libbake/colormap/colormap_reference.h"
#include "libbake/colormap/colormap_shading.h"
#include "libbake/glint/standard_normal.h"
#include "tests/colormap/test_table.h"

namespace mbk {
namespace {

test::TestTable table() { return test::banded_unit_table(); }

// n stratified standard normal samples (quantiles at (i + 0.5) / n), equal weights.
std::vector<double> normal_quantiles(int n) {
  std::vector<double> z;
  for (int i = 0; i < n; ++i) z.push_back(standard_normal_quantile((i + 0.5) / n));
  return z;
}

TEST(ColormapReference, TextureOfGaussianSamplesIsTheTableLookup) {
  const auto t = table();
  std::vector<WeightedValue> samples;
  for (double z : normal_quantiles(20000)) samples.push_back({0.47 + 0.12 * z, 1.0});
  const Vec3 reference = reference_texture_colormap(t.baked.curve, samples);
  const Vec3 filtered = texture_colormap(t.baked.table, 0.47, 0.12, ColormapFiltering::texture);
  EXPECT_LT((reference - filtered).cwiseAbs().maxCoeff(), 1e-3);
}

TEST(ColormapReference, HeightsOfAGaussianSurfaceGiveEq14) {
  const auto t = table();
  Microsurface s;
  s.sigma_h = 0.1, s.height_offset = 0.5;
  s.slopes.covariance = Mat2::Identity() * 0.09;
  std::vector<WeightedValue> heights;
  for (double z : normal_quantiles(20000)) heights.push_back({s.sigma_h * z, 1.0});
  for (const auto& [theta_o, theta_i] : {std::pair{0.0, 0.0}, {60.0, 30.0}, {85.0, 70.0}}) {
    const Vec3 wo(std::sin(theta_o * M_PI / 180), 0, std::cos(theta_o * M_PI / 180));
    const Vec3 wi(0, std::sin(theta_i * M_PI / 180), std::cos(theta_i * M_PI / 180));
    const double lo = smith_lambda(wo, s.slopes.covariance), li = smith_lambda(wi, s.slopes.covariance);
    const Vec3 reference = reference_height_colormap(t.baked.curve, heights, s.sigma_h, s.height_offset, lo, li);
    const HeightColormap filtered = height_colormap(t.baked.table, s, wo, wi, ColormapFiltering::filtered);
    // The Gaussian stand-in for D_h and the fitted moments (height_filtering_test.cpp measures them).
    EXPECT_LT((reference - filtered.color).cwiseAbs().maxCoeff(), 0.02) << theta_o << " " << theta_i;
  }
  EXPECT_EQ(reference_height_colormap(t.baked.curve, heights, 0.1, 0.5, 0.3, INFINITY), Vec3::Zero());
  EXPECT_EQ(reference_height_colormap(t.baked.curve, {}, 0.1, 0.5, 0.3, 0.3), Vec3::Zero());
}

TEST(ColormapReference, SlopesOfAGaussianSurfaceGiveTheMomentMatchedColour) {
  const auto t = table();
  Microsurface s;
  s.slopes.mean = Vec2(0.05, -0.1);
  s.slopes.covariance << 0.09, 0.01, 0.01, 0.05;
  const Eigen::LLT<Mat2> llt(s.slopes.covariance);
  const Mat2 L = llt.matrixL();
  std::vector<WeightedSlope> slopes;
  const std::vector<double> z = normal_quantiles(400);
  for (double a : z)
    for (double b : z) slopes.push_back({s.slopes.mean + L * Vec2(a, b), 1.0});
  const Vec2 d = Vec2(0.6, 0.8);
  for (double theta : {0.0, 50.0, 80.0}) {
    const Vec3 wo(std::sin(theta * M_PI / 180) * 0.8, std::sin(theta * M_PI / 180) * 0.6, std::cos(theta * M_PI / 180));
    const Vec3 reference = reference_slope_colormap(t.baked.curve, slopes, d, 0.5, wo);
    const Vec3 filtered = slope_colormap(t.baked.table, s, d, 0.5, wo, ColormapFiltering::filtered);
    EXPECT_LT((reference - filtered).cwiseAbs().maxCoeff(), 0.02) << theta;
  }
}

}  // namespace
}  // namespace mbk
