// Tests of the histogram effect's roughness lobe (libbake/histogram/roughness_lobe.h) and zonal-harmonic table
// (roughness_zh_table.h, [Shah24] Secs. 4.3.1-4.3.3): every table row against an independent quadrature of the
// reflected lobe's profile; Eq. 13 (the rotated zonal lobe Lambda_l Y_lm(w)) against a direct SH projection of the
// rotated lobe, and at the poles at orders 60 and 128; linear interpolation in roughness against the exact factors
// at midpoints, within its derived bound; the narrowest resolved roughness; the lobe's normalisation and its
// sampler's distribution, about tilted axes and the poles.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "libbake/core/gauss_legendre.h"
#include "libbake/core/sh_basis.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/histogram/roughness_lobe.h"
#include "libbake/histogram/roughness_zh_table.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

// Lambda_l of the zonal lobe e^{kappa (t - 1)} by quadrature in u = kappa (1 - t): integral of e^{-u} P_l(1 - u /
// kappa) over [0, min(2 kappa, 60)] divided by the integral of e^{-u}, composite Gauss-Legendre with panels for e^{-u}
// and for P_L's oscillation.
std::vector<double> quadrature_band_factors(double kappa, int order) {
  const double range = std::min(2.0 * kappa, 60.0);
  const int panels = int(std::ceil(range)) + int(std::ceil(order * range / kappa));
  std::vector<double> sum(size_t(order) + 1, 0.0);
  double mass = 0.0;
  for (const QuadratureNode& q : composite_gauss_legendre(0.0, range, panels, 16)) {
    const double w = q.w * std::exp(-q.x), t = 1.0 - q.x / kappa;
    mass += w;
    double p_prev = 1.0, p = t;
    sum[0] += w;
    if (order >= 1) sum[1] += w * t;
    for (int l = 1; l < order; ++l) {
      const double next = ((2.0 * l + 1.0) * t * p - l * p_prev) / (l + 1.0);
      p_prev = p;
      p = next;
      sum[size_t(l) + 1] += w * p;
    }
  }
  for (double& s : sum) s /= mass;
  return sum;
}

// Eq. 13: g_lm = Lambda_l Y_lm(w).
std::vector<double> rotated_zonal_lobe(const ShBasisEvaluator& basis, const Vec3& w,
                                       const std::vector<double>& lambda) {
  std::vector<double> g = basis.evaluate(w);
  for (int l = 0; l <= basis.order(); ++l)
    for (int m = -l; m <= l; ++m) g[size_t(sh_index(l, m))] *= lambda[size_t(l)];
  return g;
}

TEST(RoughnessZhTable, RowsMatchQuadratureOfTheLobe) {
  const RoughnessZhTable table(128);
  for (const int k : {1, 2, 10, 33, 100, 250, 500, 1000}) {
    const double s = double(k) / RoughnessZhTable::kSteps;
    const std::vector<double> expected = quadrature_band_factors(1.0 / (4.0 * s * s), 128);
    for (int l = 0; l <= 128; ++l)
      EXPECT_NEAR(table.row(k)[size_t(l)], expected[size_t(l)], 1e-12 + 1e-10 * expected[size_t(l)])
          << "k " << k << ", l " << l;
  }
  for (const double lambda : table.row(0)) EXPECT_EQ(lambda, 1.0);  // the mirror lobe
}

TEST(RoughnessZhTable, InterpolatedRoughnessIsCloseToExactAtMidpoints) {
  // Linear interpolation in s errs by at most h^2 / 8 max |d^2 Lambda / d s^2|, h = 1e-3. The reflected lobe's
  // Lambda_l ~ exp(-a s^2), a = 2 l (l + 1), has |d^2 / d s^2| <= 2a (at s = 0), so the error is below
  // h^2 l (l + 1) / 2 = 1.83e-3 at l = 60.
  const RoughnessZhTable table(60);
  std::vector<double> interpolated(61), exact(61);
  double worst = 0.0;
  for (int k = 1; k < RoughnessZhTable::kSteps; k += 7) {
    const double s = (k + 0.5) / RoughnessZhTable::kSteps;
    table.band_factors(s, interpolated);
    vmf_band_factors(1.0 / (4.0 * s * s), exact);
    for (int l = 0; l <= 60; ++l) worst = std::max(worst, std::abs(interpolated[size_t(l)] - exact[size_t(l)]));
  }
  std::cout << "largest |interpolated - exact| Lambda_l at midpoints, order 60: " << worst << "\n";
  EXPECT_LT(worst, 1e-6 * 60 * 61 / 2);
  table.band_factors(0.25, interpolated);  // at a tabulated point it is the row itself
  for (int l = 0; l <= 60; ++l) EXPECT_EQ(interpolated[size_t(l)], table.row(250)[size_t(l)]);
}

// A direct projection of the rotated lobe onto the basis: Gauss-Legendre in cos(theta) times a uniform phi rule,
// fine enough for order 16 and kappa <= 400.
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
  for (const double kappa : {0.5, 4.0, 30.0, 120.0, 400.0, 2.0}) {
    const Vec3 mu = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    std::vector<double> lambda(size_t(order) + 1);
    vmf_band_factors(kappa, lambda);
    const std::vector<double> rotated = rotated_zonal_lobe(basis, mu, lambda);
    const std::vector<double> direct = project_rotated_lobe(mu, kappa, order);
    for (size_t k = 0; k < rotated.size(); ++k)
      EXPECT_NEAR(rotated[k], direct[k], 2e-6) << "kappa " << kappa << ", k " << k;
  }
}

TEST(RoughnessZhTable, RotatedLobesAtThePolesAreFiniteAndZonal) {
  for (const int order : {60, 128}) {
    const ShBasisEvaluator basis(order);
    std::vector<double> lambda(size_t(order) + 1);
    vmf_band_factors(1.0 / (4.0 * 0.01 * 0.01), lambda);
    for (const double z : {1.0, -1.0}) {
      const std::vector<double> g = rotated_zonal_lobe(basis, Vec3(0, 0, z), lambda);
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
    // Just off the pole, where sin(theta)^m underflows for large m, every value stays finite.
    for (const double v : rotated_zonal_lobe(basis, Vec3(1e-300, 0, 1).normalized(), lambda))
      ASSERT_TRUE(std::isfinite(v));
  }
}

TEST(RoughnessZhTable, NarrowestResolvedRoughnessLeavesAnEighthOfTheLastBand) {
  // Defined through the large-l form exp(-l (l + 1) / (2 kappa)) = e^{-2}; the exact Bessel ratio is within 6% of it
  // from order 8 up (the form's next term, l (l + 1) / (4 kappa^2), is 0.055 at L = 8 and falls as 1 / L^2).
  for (const int order : {8, 20, 40, 64, 128}) {
    const double s = narrowest_resolved_roughness(order);
    EXPECT_NEAR(2.0 * s * s * order * (order + 1.0), 2.0, 1e-12) << order;
    std::vector<double> lambda(size_t(order) + 1);
    vmf_band_factors(1.0 / (4.0 * s * s), lambda);
    EXPECT_NEAR(lambda.back() / std::exp(-2.0), 1.0, 0.06) << order << ": " << lambda.back();
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
  // The sampler: the mean of w . mu is A(kappa) of the vMF, the mean of w is A mu (no sideways bias), every sample is
  // unit; about a tilted axis and about both poles (the frame's special cases).
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (const Vec3& mu : {Vec3(Vec3(0.3, -0.5, 0.8).normalized()), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
    for (const double sigma : {0.01, 0.2, 1.0}) {
      Vec3 sum = Vec3::Zero();
      const int n = 100000;
      for (int i = 0; i < n; ++i) {
        const Vec3 w = sample_roughness_lobe(mu, sigma, u01(rng), u01(rng));
        ASSERT_NEAR(w.norm(), 1.0, 1e-12);
        sum += w;
      }
      const double expected = vmf_mean_length(lobe_kappa(sigma));
      const double tolerance = 5.0 * std::sqrt((1.0 - expected * expected) / n) + 1e-6;
      EXPECT_NEAR(sum.dot(mu) / n, expected, tolerance) << sigma;
      EXPECT_NEAR((sum / n - expected * mu).norm(), 0.0, 2.0 * tolerance) << sigma;
    }
  }
}

}  // namespace
}  // namespace mbk
