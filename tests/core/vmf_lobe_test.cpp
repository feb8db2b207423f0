// Tests of the vMF lobe functions (libbake/core/vmf_lobe.h): A(kappa) and its inverse against a long-double
// bisection reference, the closed form's error that the Newton solve removes, the r -> 0 and r -> 1 limits,
// a density that integrates to 1 without overflow, and the Bessel-ratio band factors against quadrature.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "formats/error.h"
#include "libbake/core/gauss_legendre.h"
#include "libbake/core/vmf_lobe.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

// Reference A and 1 - A in long double (64-bit mantissa on x86): a long series for small kappa, else
// 1 - A = 1/k - 2 e^-2k / (1 - e^-2k).
long double one_minus_a_ld(long double k) { return 1.0L / k - 2.0L * std::exp(-2.0L * k) / -std::expm1(-2.0L * k); }
long double a_ld(long double k) {
  if (k < 0.05L) {
    const long double k2 = k * k;
    return k * (1.0L / 3 - k2 / 45 + 2 * k2 * k2 / 945 - k2 * k2 * k2 / 4725 + 2 * k2 * k2 * k2 * k2 / 93555 -
                1382 * k2 * k2 * k2 * k2 * k2 / 638512875.0L);
  }
  return 1.0L - one_minus_a_ld(k);
}

// Bisection (in log kappa) on the reference, to long-double resolution.
double reference_kappa(double r) {
  const bool upper = r > 0.5;
  const long double target = upper ? 1.0L - (long double)r : (long double)r;
  long double lo = 1e-12L, hi = 1e20L;
  for (int it = 0; it < 400; ++it) {
    const long double mid = std::sqrt(lo * hi);
    const bool below = upper ? one_minus_a_ld(mid) > target : a_ld(mid) < target;
    (below ? lo : hi) = mid;
  }
  return double(std::sqrt(lo * hi));
}

TEST(VmfLobe, MeanLengthMatchesLongDouble) {
  for (double k : {1e-8, 1e-3, 0.05, 0.0999, 0.1, 0.1001, 0.5, 1.0, 1.999, 2.0, 3.0, 20.0, 39.999, 40.0, 40.001, 100.0,
                   1e4, 1e6, 1e9}) {
    EXPECT_NEAR(vmf_mean_length(k), double(a_ld(k)), 1e-15 * double(a_ld(k)) + 1e-300) << k;
    if (k >= 0.1) {
      EXPECT_NEAR(vmf_one_minus_mean_length(k), double(one_minus_a_ld(k)), 1e-15 * double(one_minus_a_ld(k))) << k;
    }
  }
  EXPECT_EQ(vmf_mean_length(0.0), 0.0);
  EXPECT_EQ(vmf_one_minus_mean_length(std::numeric_limits<double>::infinity()), 0.0);
}

// Above kappa = 40 the functions drop e^-2k instead of computing it: the bits are those of the full formula.
TEST(VmfLobe, LargeKappaDropsTheExponentialWithTheSameBits) {
  for (double k : {40.0000001, 41.0, 1e3, 1e6, 1e9}) {
    EXPECT_EQ(vmf_one_minus_mean_length(k), 1.0 / k - 2.0 * std::exp(-2.0 * k) / -std::expm1(-2.0 * k)) << k;
    EXPECT_EQ(vmf_log_density(k, 0.5), std::log(k / (2.0 * std::numbers::pi * -std::expm1(-2.0 * k))) + k * -0.5) << k;
  }
}

TEST(VmfLobe, KappaSolveMatchesHighPrecisionReference) {
  std::vector<double> rs;
  for (double e = -6; e <= -0.31; e += 0.25) rs.push_back(std::pow(10.0, e));
  for (double e = -0.3; e >= -12; e -= 0.25) rs.push_back(1.0 - std::pow(10.0, e));
  rs.push_back(1.0 - 1e-12);
  rs.push_back(0.5);
  for (double r : rs) {
    const double k = vmf_kappa_from_mean_length(r, 1e300), ref = reference_kappa(r);
    EXPECT_NEAR(k, ref, 1e-12 * ref) << "r = " << r;
  }
}

// Why the Newton solve: Banerjee's closed form is several percent off in the middle of the range.
TEST(VmfLobe, ClosedFormIsPercentsOffNewtonIsExact) {
  double worst_closed = 0.0, worst_newton = 0.0;
  for (double r = 0.01; r < 0.999; r += 0.001) {
    const double ref = reference_kappa(r);
    worst_closed = std::max(worst_closed, std::abs(vmf_kappa_closed_form(r) - ref) / ref);
    worst_newton = std::max(worst_newton, std::abs(vmf_kappa_from_mean_length(r, 1e300) - ref) / ref);
  }
  EXPECT_GT(worst_closed, 0.03);
  EXPECT_LT(worst_closed, 0.07);
  EXPECT_LT(worst_newton, 1e-13);
}

TEST(VmfLobe, KappaCappedAsRApproachesOne) {
  const double cap = 1e5;
  EXPECT_EQ(vmf_kappa_from_mean_length(1.0, cap), cap);
  EXPECT_EQ(vmf_kappa_from_mean_length(1.0 + 1e-15, cap), cap);  // rounding past 1 (identical normals)
  EXPECT_EQ(vmf_kappa_from_mean_length(1.0 - 1e-9, cap), cap);   // A(1e5) = 1 - 1e-5 < r
  EXPECT_LT(vmf_kappa_from_mean_length(1.0 - 1e-4, cap), cap);
  EXPECT_NEAR(vmf_kappa_from_mean_length(vmf_mean_length(500.0), cap), 500.0, 1e-9);
}

TEST(VmfLobe, KappaTendsToThreeRAsRTendsToZero) {
  EXPECT_EQ(vmf_kappa_from_mean_length(0.0, 1e5), 0.0);
  EXPECT_EQ(vmf_kappa_from_mean_length(-0.25, 1e5), 0.0);
  EXPECT_NEAR(vmf_kappa_from_mean_length(1e-12, 1e5), 3e-12, 1e-24);
  EXPECT_NEAR(vmf_kappa_from_mean_length(1e-300, 1e5), 3e-300, 1e-312);
  EXPECT_THROW(vmf_kappa_from_mean_length(std::nan(""), 1e5), Error);
}

// 2 pi integral of g over cos(angle) = 1, for concentrations from uniform to far past exp overflow.
TEST(VmfLobe, LogDensityIntegratesToOneWithoutOverflow) {
  for (double k : {0.0, 1e-10, 0.3, 10.0, 800.0, 1e5, 1e7}) {
    const double width = std::min(2.0, 80.0 / std::max(k, 1e-300));
    const std::vector<QuadratureNode> rule = composite_gauss_legendre(1.0 - width, 1.0, 1, 200);
    double sum = 0.0;
    for (size_t i = 0; i < rule.size(); ++i) {
      const double v = vmf_log_density(k, rule[i].x);
      ASSERT_TRUE(std::isfinite(v)) << k;
      sum += rule[i].w * std::exp(v);
    }
    // Nodes near t = 1 carry an absolute rounding error of ~1e-16, which the exponent multiplies by kappa.
    EXPECT_NEAR(2 * kPi * sum, 1.0, 1e-12 + 1e-16 * k) << "kappa = " << k;
  }
}

// Lambda_l = 2 pi integral g(t) P_l(t) dt (Funk-Hecke), by quadrature where the lobe lives.
TEST(VmfLobe, BandFactorsMatchQuadrature) {
  constexpr int L = 24;
  // With L = 24 the forward recurrence takes kappa >= max(8, L^2 / 2) = 288: 288, 1000 and 2e4; the backward one
  // 1e-3, 0.5, 2, 10 and 100; 1e6 is the asymptotic branch.
  for (double k : {1e-3, 0.5, 2.0, 10.0, 100.0, 288.0, 1000.0, 2e4, 1e6}) {
    std::vector<double> lambda(L + 1);
    vmf_band_factors(k, lambda);
    const double width = std::min(2.0, 80.0 / k);
    const std::vector<QuadratureNode> rule = composite_gauss_legendre(1.0 - width, 1.0, 1, 400);
    for (int l = 0; l <= L; ++l) {
      double sum = 0.0;
      for (size_t i = 0; i < rule.size(); ++i) {
        const double t = rule[i].x;
        double p0 = 1.0, p1 = t;
        for (int n = 2; n <= l; ++n) {
          const double p2 = ((2.0 * n - 1.0) * t * p1 - (n - 1.0) * p0) / n;
          p0 = p1;
          p1 = p2;
        }
        sum += rule[i].w * std::exp(vmf_log_density(k, t)) * (l == 0 ? 1.0 : p1);
      }
      EXPECT_NEAR(lambda[size_t(l)], 2 * kPi * sum, 1e-10) << "kappa " << k << " l " << l;
    }
    EXPECT_NEAR(lambda[1], vmf_mean_length(k), 1e-14);
    EXPECT_NEAR(lambda[2], 1.0 - 3.0 * vmf_mean_length(k) / k, 1e-12);
  }
}

// The forward recurrence takes over from the backward one at kappa = max(8, L^2 / 2): the two agree there to
// rounding, for low and high orders (measured up to 4e-15 relative over L <= 128).
TEST(VmfLobe, BandFactorsBranchesAgreeWhereTheySwitch) {
  for (const int order : {1, 2, 3, 4, 8, 16, 32, 64, 128}) {
    const double at = std::max(8.0, 0.5 * order * order);
    std::vector<double> below(size_t(order) + 1), above(size_t(order) + 1);
    vmf_band_factors(std::nextafter(at, 0.0), below);
    vmf_band_factors(at, above);
    for (int l = 0; l <= order; ++l)
      EXPECT_NEAR(above[size_t(l)] / below[size_t(l)], 1.0, 2e-14) << "order " << order << " l " << l;
  }
}

TEST(VmfLobe, BandFactorsLimitsAndAsymptoticSwitch) {
  std::vector<double> a(9), b(9);
  vmf_band_factors(0.0, a);
  EXPECT_EQ(a[0], 1.0);
  EXPECT_EQ(a[8], 0.0);
  vmf_band_factors(std::numeric_limits<double>::infinity(), a);
  EXPECT_EQ(a[8], 1.0);
  // The forward recurrence and the asymptotic agree where the switch is (kappa^3 = 5e11 (order + 1)^4, where the
  // asymptotic is least accurate), for the diffuse order of the vmf shader and for a low one.
  for (const int order : {8, 32}) {
    std::vector<double> below(size_t(order) + 1), above(size_t(order) + 1);
    const double top = order + 1.0, at = std::cbrt(5e11 * top * top * top * top);
    vmf_band_factors(at * (1 - 1e-12), below);  // 1e-12 apart: Lambda moves by < 1e-15 between the two
    vmf_band_factors(at * (1 + 1e-12), above);
    // Measured up to 7.8e-14 for order 32: the asymptotic's own error there (against 40-digit Bessel ratios).
    for (int l = 0; l <= order; ++l) EXPECT_NEAR(below[size_t(l)], above[size_t(l)], 2e-13) << order << " " << l;
  }
}

}  // namespace
}  // namespace mbk
