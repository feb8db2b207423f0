// Tests of the histogram effect's roughness lobe and zonal-harmonic table (libbake/histogram/roughness_zh_table.h,
// [Shah24] Secs. 4.3.1-4.3.3): the quadrature band factors against the closed-form Bessel ratios of vmf_lobe.h; the
// rotated zonal lobe (Eq. 13) against a direct SH projection of the rotated lobe; finiteness and exactness at the
// poles at order 60 and 128; linear interpolation in roughness against the exact factors at midpoints; the lobe's
// normalisation and its sampler's distribution.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "libbake/core/gauss_legendre.h"
#include "libbake/core/sh_basis.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/histogram/roughness_zh_table.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(RoughnessZhTable, QuadratureMatchesTheBesselRatios) {
  for (const double kappa : {0.25, 1.0, 3.0, 25.0, 250.0, 2.5e3, 2.5e5}) {
    for (const int order : {0, 1, 8, 60, 128}) {
      std::vector<double> quadrature(size_t(order) + 1), closed(size_t(order) + 1);
      zonal_lobe_band_factors(kappa, quadrature);
      vmf_band_factors(kappa, closed);
      for (int l = 0; l <= order; ++l)
        EXPECT_NEAR(quadrature[size_t(l)], closed[size_t(l)], 1e-12 + 1e-10 * closed[size_t(l)])
            << "kappa " << kappa << ", l " << l;
    }
  }
}

TEST(RoughnessZhTable, RowsAreTheReflectedLobesFactors) {
  const RoughnessZhTable table(60);
  std::vector<double> expected(61);
  for (const int k : {1, 2, 10, 33, 100, 500, 1000}) {
    const double sigma = double(k) / RoughnessZhTable::kSteps;
    vmf_band_factors(1.0 / (4.0 * sigma * sigma), expected);
    for (int l = 0; l <= 60; ++l) EXPECT_NEAR(table.row(k)[size_t(l)], expected[size_t(l)], 1e-11) << k << " " << l;
  }
  for (const double lambda : table.row(0)) EXPECT_EQ(lambda, 1.0);  // the mirror lobe
}

TEST(RoughnessZhTable, InterpolatedRoughnessIsCloseToExactAtMidpoints) {
  // Linear interpolation in sigma errs by at most h^2 / 8 max |d^2 Lambda / d sigma^2|, h = 1e-3. The reflected lobe's
  // Lambda_l ~ exp(-a sigma^2), a = 2 l (l + 1), has |d^2 / d sigma^2| <= 2a (at sigma = 0), so the error is below
  // h^2 l (l + 1) / 2 = 1.83e-3 at l = 60.
  const RoughnessZhTable table(60);
  std::vector<double> interpolated(61), exact(61);
  double worst = 0.0;
  for (int k = 1; k < RoughnessZhTable::kSteps; k += 7) {
    const double sigma = (k + 0.5) / RoughnessZhTable::kSteps;
    table.band_factors(sigma, interpolated);
    vmf_band_factors(1.0 / (4.0 * sigma * sigma), exact);
    for (int l = 0; l <= 60; ++l) worst = std::max(worst, std::abs(interpolated[size_t(l)] - exact[size_t(l)]));
  }
  std::cout << "largest |interpolated - exact| Lambda_l at midpoints, order 60: " << worst << "\n";
  EXPECT_LT(worst, 1e-6 * 60 * 61 / 2);
  // At the tabulated points themselves it is exact.
  table.band_factors(0.25, interpolated);
  for (int l = 0; l <= 60; ++l) EXPECT_EQ(interpolated[size_t(l)], table.row(250)[size_t(l)]);
}

// A direct projection of the rotated lobe onto the basis: Gauss-Legendre in cos(theta) (panels concentrated where the
// lobe is) times a uniform phi rule, fine enough for order 16 and kappa <= 400.
std::vector<double> project_rotated_lobe(const Vec3& mu, double kappa, int order) {
  const ShBasisEvaluator basis(order);
  std::vector<double> out(size_t(basis.count()), 0.0), y(out.size());
  const int phi_steps = 512;
  for (const QuadratureNode& q : composite_gauss_legendre(-1.0, 1.0, 256, 16)) {
    const double s = std::sqrt(std::max(0.0, 1.0 - q.x * q.x));
    for (int i = 0; i < phi_steps; ++i) {
      const double phi = 2.0 * kPi * (i + 0.5) / phi_steps;
      const Vec3 w(s * std::cos(phi), s * std::sin(phi), q.x);
      const double g = std::exp(vmf_log_density(kappa, w.dot(mu)));
      basis.evaluate(w, y);
      for (size_t k = 0; k < out.size(); ++k) out[k] += q.w * (2.0 * kPi / phi_steps) * g * y[k];
    }
  }
  return out;
}

TEST(RoughnessZhTable, RotatedZonalLobeEqualsTheProjectionOfTheRotatedLobe) {
  std::mt19937_64 rng(13);
  std::normal_distribution<double> normal;
  const int order = 16;
  const ShBasisEvaluator basis(order);
  std::vector<double> y(size_t(basis.count()));
  for (int trial = 0; trial < 6; ++trial) {
    const Vec3 mu = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    const double kappa = std::array{0.5, 4.0, 30.0, 120.0, 400.0, 2.0}[size_t(trial)];
    std::vector<double> lambda(size_t(order) + 1);
    zonal_lobe_band_factors(kappa, lambda);
    std::vector<double> rotated(size_t(basis.count()), 0.0);
    add_rotated_zonal_lobe(basis, mu, lambda, 1.0, rotated, y);
    const std::vector<double> direct = project_rotated_lobe(mu, kappa, order);
    for (size_t k = 0; k < rotated.size(); ++k)
      EXPECT_NEAR(rotated[k], direct[k], 2e-6) << "kappa " << kappa << ", k " << k;
  }
}

TEST(RoughnessZhTable, RotatedLobesAtThePolesAreFiniteAndZonal) {
  for (const int order : {60, 128}) {
    const ShBasisEvaluator basis(order);
    std::vector<double> y(size_t(basis.count())), lambda(size_t(order) + 1), g(size_t(basis.count()));
    zonal_lobe_band_factors(1.0 / (4.0 * 0.01 * 0.01), lambda);
    for (const double z : {1.0, -1.0}) {
      std::fill(g.begin(), g.end(), 0.0);
      add_rotated_zonal_lobe(basis, Vec3(0, 0, z), lambda, 1.0, g, y);
      for (int l = 0; l <= order; ++l)
        for (int m = -l; m <= l; ++m) {
          const double v = g[size_t(sh_index(l, m))];
          ASSERT_TRUE(std::isfinite(v));
          // At the pole only m = 0 survives, Y_l0(+-z) = (+-1)^l sqrt((2l + 1) / (4 pi)).
          const double expected =
              m == 0 ? lambda[size_t(l)] * std::pow(z, l) * std::sqrt((2.0 * l + 1.0) / (4.0 * kPi)) : 0.0;
          EXPECT_NEAR(v, expected, 1e-12 * (1.0 + std::abs(expected))) << "order " << order << " l " << l << " m " << m;
        }
    }
    // Just off the pole, where sin(theta)^m underflows for large m, every value stays finite and bounded.
    std::fill(g.begin(), g.end(), 0.0);
    add_rotated_zonal_lobe(basis, Vec3(1e-300, 0, 1).normalized(), lambda, 1.0, g, y);
    for (const double v : g) ASSERT_TRUE(std::isfinite(v));
  }
}

TEST(RoughnessZhTable, NarrowestResolvedRoughnessLeavesAnEighthOfTheLastBand) {
  for (const int order : {1, 8, 20, 40, 60, 128}) {
    const double sigma = narrowest_resolved_roughness(order);
    std::vector<double> lambda(size_t(order) + 1);
    vmf_band_factors(1.0 / (4.0 * sigma * sigma), lambda);
    EXPECT_NEAR(lambda.back(), std::exp(-2.0), 0.03) << order;  // exp(-l (l + 1) / (2 kappa)) is the large-l form
  }
}

TEST(RoughnessZhTable, LobeIsNormalisedAndItsSamplerFollowsIt) {
  for (const double sigma : {1e-3, 0.01, 0.1, 0.5, 1.0}) {
    double mass = 0.0;
    const double kappa = lobe_kappa(sigma);
    for (const QuadratureNode& q : composite_gauss_legendre(0.0, std::min(2.0 * kappa, 60.0), 200, 16))
      mass += q.w / kappa * 2.0 * kPi * roughness_lobe(1.0 - q.x / kappa, sigma);
    EXPECT_NEAR(mass, 1.0, 1e-10) << sigma;
  }
  // The sampler: mean of w . mu equals A(kappa) of the vMF, and every sample is unit; about a tilted axis.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const Vec3 mu = Vec3(0.3, -0.5, 0.8).normalized();
  for (const double sigma : {0.01, 0.2, 1.0}) {
    double sum = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const Vec3 w = sample_roughness_lobe(mu, sigma, u01(rng), u01(rng));
      ASSERT_NEAR(w.norm(), 1.0, 1e-12);
      sum += w.dot(mu);
    }
    const double expected = vmf_mean_length(lobe_kappa(sigma));
    EXPECT_NEAR(sum / n, expected, 5.0 * std::sqrt((1.0 - expected * expected) / n) + 1e-6) << sigma;
  }
  // The axis at the poles too (the frame's singular case).
  for (const double z : {1.0, -1.0}) EXPECT_NEAR(sample_roughness_lobe(Vec3(0, 0, z), 0.01, 0.0, 0.3).z(), z, 1e-12);
}

}  // namespace
}  // namespace mbk
