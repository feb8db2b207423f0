// The standard normal distribution (libbake/glint/standard_normal.h): Phi and Phi^-1 against reference values
// computed with mpmath at 50 digits, the round trip Phi(Phi^-1(p)) = p from p = 1e-300 to 1 - 2^-53 within the
// conditioning of Phi, exact symmetry of the tails, monotonicity, and the edge cases.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libbake/glint/standard_normal.h"

namespace mbk {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(StandardNormal, QuantileMatchesReferenceValues) {
  // mpmath: findroot(log(ncdf(x)) - log(p)) with mp.dps = 50.
  const std::pair<double, double> reference[] = {
      {1e-300, -37.047096299361199237},      {1e-100, -21.273453560965324295}, {1e-20, -9.2623400897984075737},
      {1e-10, -6.3613409024040562047},       {1e-5, -4.2648907939228246285},   {0.001, -3.0902323061678135415},
      {0.025, -1.9599639845400542355},       {0.3, -0.52440051270804078404},   {0.5, 0.0},
      {0.75, 0.6744897501960817432},         {0.975, 1.9599639845400542355},   {0.999, 3.0902323061678135415},
      {1.0 - 0x1p-53, 8.2095361516013868556}};
  for (const auto& [p, x] : reference) {
    // The decimal p is rounded to double (relative 2^-53): dx = dp / phi(x) ~ eps p / phi(x) <= eps / |x|.
    EXPECT_NEAR(standard_normal_quantile(p), x, 4 * kEps * std::max(1.0, std::abs(x))) << "p = " << p;
  }
}

TEST(StandardNormal, CdfMatchesReferenceValues_LowerTailRelative) {
  const std::pair<double, double> reference[] = {
      {-37.0, 5.7255712225245768227e-300}, {-20.0, 2.7536241186062336951e-89}, {-10.0, 7.619853024160526066e-24},
      {-5.0, 2.8665157187919391167e-7},    {-1.0, 0.15865525393145705141},     {0.0, 0.5},
      {0.5, 0.69146246127401310364},       {1.96, 0.97500210485177956586},     {3.0, 0.99865010196836990547},
      {8.0, 0.9999999999999993779}};
  for (const auto& [x, p] : reference) {
    // Relative conditioning of Phi at x is about x^2 (x phi(x) / Phi(x)); erfc adds a few ulps.
    EXPECT_NEAR(standard_normal_cdf(x), p, 4 * kEps * (1 + x * x) * p) << "x = " << x;
  }
}

TEST(StandardNormal, RoundTripFrom1e300To1Minus1e16) {
  // Lower half: p = 10^(-300 .. -0.302) on a fine logarithmic grid; relative error within the conditioning
  // of Phi (a 1-ulp change of x moves Phi by about x^2 ulps relative).
  for (int i = 0; i <= 30000; ++i) {
    const double p = std::pow(10.0, -300.0 + i * (300.0 - 0.30103) / 30000.0);
    const double x = standard_normal_quantile(p);
    ASSERT_TRUE(std::isfinite(x)) << p;
    ASSERT_NEAR(standard_normal_cdf(x), p, 8 * kEps * (1 + x * x) * p) << "p = " << p;
  }
  // Upper half: p = 1 - q for q from 0.5 down to 1e-16: the complement 1 - p is exact, so check it relatively
  // through the lower tail, and p itself absolutely.
  for (int i = 0; i <= 3000; ++i) {
    const double p = 1.0 - std::pow(10.0, -0.30103 - i * (16.0 - 0.30103) / 3000.0);
    const double x = standard_normal_quantile(p);
    ASSERT_TRUE(std::isfinite(x)) << p;
    ASSERT_NEAR(standard_normal_cdf(-x), 1.0 - p, 8 * kEps * (1 + x * x) * (1.0 - p)) << "p = " << p;
    ASSERT_NEAR(standard_normal_cdf(x), p, 2 * kEps) << "p = " << p;
  }
}

TEST(StandardNormal, TailsAreExactMirrors) {
  for (double q : {0x1p-60, 1e-17, 0x1p-20, 1e-3, 0.1, 0.25, 0.4999}) {
    // 1 - q is exact for these q (q is a power of two or 1 - q rounds only when q < 2^-53, where Phi^-1(1) = inf).
    const double p = 1.0 - q;
    if (p == 1.0) {
      EXPECT_EQ(standard_normal_quantile(p), std::numeric_limits<double>::infinity());
      continue;
    }
    EXPECT_EQ(standard_normal_quantile(p), -standard_normal_quantile(1.0 - p)) << q;
  }
}

TEST(StandardNormal, QuantileIsMonotoneOnFineGrids) {
  // Between arguments further apart than its accuracy, Phi^-1 never decreases (the rank-to-Gaussian map of the
  // standardization relies on it); a linear grid and a logarithmic grid through the lower tail.
  double previous = -std::numeric_limits<double>::infinity();
  for (int i = 1; i < 200000; ++i) {
    const double x = standard_normal_quantile(i / 200000.0);
    ASSERT_GT(x, previous) << i;
    previous = x;
  }
  previous = -std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 100000; ++i) {
    const double x = standard_normal_quantile(std::pow(10.0, -300.0 + i * 299.0 / 100000.0));
    ASSERT_GT(x, previous) << i;
    previous = x;
  }
}

TEST(StandardNormal, EdgeCases) {
  EXPECT_EQ(standard_normal_quantile(0.5), 0.0);
  EXPECT_EQ(standard_normal_quantile(0.0), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(standard_normal_quantile(-1.0), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(standard_normal_quantile(1.0), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(standard_normal_quantile(std::nan(""))));
  EXPECT_TRUE(std::isfinite(standard_normal_quantile(std::numeric_limits<double>::denorm_min())));
  EXPECT_EQ(standard_normal_cdf(-std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_EQ(standard_normal_cdf(std::numeric_limits<double>::infinity()), 1.0);
  EXPECT_NEAR(standard_normal_pdf(0.0), 0.39894228040143267794, kEps);
  EXPECT_NEAR(standard_normal_pdf(3.0), 0.0044318484119380075, 4 * kEps * 0.0044318484119380075);
}

}  // namespace
}  // namespace mbk
