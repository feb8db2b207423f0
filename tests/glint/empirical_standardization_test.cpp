// The exact standardization transform (libbake/glint/empirical_standardization.h): mid-ranks against a brute-force
// average of tied positions, G^-1 undoing G, the constant and two-valued hard cases, the clipped tail mass, and
// full precision in both tails.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "formats/error.h"
#include "libbake/core/hash.h"
#include "libbake/glint/empirical_standardization.h"
#include "libbake/glint/standard_normal.h"

namespace mbk {
namespace {

// Values with many ties: k levels, hashed counts.
std::vector<float> tied_values(uint32_t n, uint32_t levels, uint32_t seed) {
  std::vector<float> v(n);
  for (uint32_t i = 0; i < n; ++i) v[i] = float(int(hash3(i, seed, 0) % levels) - int(levels / 2)) * 0.125f;
  return v;
}

std::vector<float> continuous_values(uint32_t n, uint32_t seed) {
  std::vector<float> v(n);
  for (uint32_t i = 0; i < n; ++i) {
    const double u = (hash3(i, seed, 0) + 0.5) / 4294967296.0;
    v[i] = float(0.4 * std::tanh(standard_normal_quantile(u)) + 0.01 * std::sin(double(i)));
  }
  return v;
}

TEST(EmpiricalStandardization, TiesShareOneGaussianValue) {
  const std::vector<float> v = tied_values(1001, 7, 3);
  const EmpiricalStandardization g(v);
  EXPECT_EQ(g.distinct_values(), 7u);
  // Brute force: sort, and for each value average its 1-based positions; F = (average - 1/2) / N.
  std::vector<float> sorted = v;
  std::sort(sorted.begin(), sorted.end());
  std::map<float, std::pair<double, int>> positions;
  for (size_t i = 0; i < sorted.size(); ++i) {
    positions[sorted[i]].first += double(i + 1);
    positions[sorted[i]].second += 1;
  }
  for (const auto& [value, sum_count] : positions) {
    const double F = (sum_count.first / sum_count.second - 0.5) / double(v.size());
    EXPECT_NEAR(g.forward(value), standard_normal_quantile(F), 1e-14) << value;
  }
  // Every texel of one value gets the same z, whatever its position in the input.
  for (size_t i = 1; i < v.size(); ++i) {
    if (v[i] == v[0]) {
      ASSERT_EQ(g.forward(v[i]), g.forward(v[0]));
    }
  }
}

TEST(EmpiricalStandardization, InverseUndoesForward) {
  for (const auto& v : {continuous_values(4096, 1), tied_values(4096, 9, 2)}) {
    const EmpiricalStandardization g(v);
    const double range = g.max() - g.min();
    for (int i = 0; i <= 20000; ++i) {
      const double x = g.min() + range * i / 20000.0;
      ASSERT_NEAR(g.inverse(g.forward(x)), x, 1e-12 * range) << x;
    }
    for (float x : v) ASSERT_NEAR(g.inverse(g.forward(x)), x, 1e-12 * range) << x;
  }
}

TEST(EmpiricalStandardization, ForwardAndInverseAreMonotoneAndClamped) {
  const EmpiricalStandardization g(continuous_values(2000, 5));
  double previous = -INFINITY;
  for (int i = -100; i <= 10100; ++i) {
    const double z = g.forward(g.min() + (g.max() - g.min()) * i / 10000.0);
    ASSERT_GE(z, previous);
    previous = z;
  }
  EXPECT_EQ(g.forward(g.min() - 1.0), g.gaussian_min());
  EXPECT_EQ(g.forward(g.max() + 1.0), g.gaussian_max());
  EXPECT_EQ(g.forward(std::nan("")), g.gaussian_min());
  EXPECT_EQ(g.inverse(-50.0), g.min());
  EXPECT_EQ(g.inverse(50.0), g.max());
  EXPECT_EQ(g.inverse(std::nan("")), g.min());
}

TEST(EmpiricalStandardization, ConstantChannelMapsToZero) {
  const EmpiricalStandardization g(std::vector<float>(100, 0.3f));
  EXPECT_EQ(g.distinct_values(), 1u);
  EXPECT_EQ(g.gaussian_min(), 0.0);
  EXPECT_EQ(g.gaussian_max(), 0.0);
  for (double x : {-1.0, 0.3, 2.0}) EXPECT_EQ(g.forward(x), 0.0);
  for (double z : {-3.0, 0.0, 3.0}) EXPECT_EQ(g.inverse(z), double(0.3f));
  const EmpiricalStandardization one(std::vector<float>{-0.7f});  // a 1 x 1 map
  EXPECT_EQ(one.forward(-0.7f), 0.0);
  EXPECT_EQ(one.inverse(1.0), double(-0.7f));
}

TEST(EmpiricalStandardization, TwoValuedChannelHasTheClosedForm) {
  // 30 texels at -0.5 and 70 at 0.25: F = 15/100 and 65/100, linear in x between.
  std::vector<float> v(30, -0.5f);
  v.resize(100, 0.25f);
  const EmpiricalStandardization g(v);
  EXPECT_NEAR(g.gaussian_min(), standard_normal_quantile(0.15), 1e-15);
  EXPECT_NEAR(g.gaussian_max(), standard_normal_quantile(0.65), 1e-15);
  EXPECT_NEAR(g.forward(-0.125), standard_normal_quantile(0.40), 1e-15);  // halfway
  EXPECT_NEAR(g.inverse(standard_normal_quantile(0.40)), -0.125, 1e-15);
  EXPECT_NEAR(standard_normal_cdf(g.gaussian_min()) + standard_normal_cdf(-g.gaussian_max()), (30.0 + 70.0) / 200.0,
              1e-15);
}

TEST(EmpiricalStandardization, NegativeZeroIsZero) {
  const EmpiricalStandardization g(std::vector<float>{-0.0f, 0.0f, -0.0f, 1.0f});
  EXPECT_EQ(g.distinct_values(), 2u);
  EXPECT_EQ(g.forward(-0.0), g.forward(0.0));
}

TEST(EmpiricalStandardization, TailMassIsTheEndCounts) {
  std::vector<float> v = continuous_values(999, 8);
  v.push_back(*std::min_element(v.begin(), v.end()));  // the minimum twice
  const EmpiricalStandardization g(v);
  const double mass = (2.0 + 1.0) / (2.0 * 1000.0);  // (c_1 + c_K) / 2N
  EXPECT_NEAR(standard_normal_cdf(g.gaussian_min()) + standard_normal_cdf(-g.gaussian_max()), mass, 1e-15 * mass);
}

TEST(EmpiricalStandardization, BothTailsKeepFullPrecision) {
  // All distinct: G(min) = Phi^-1(1/2N) and G(max) = -Phi^-1(1/2N), exactly mirrored (the upper tail is evaluated
  // through its own mass, not through 1 - F, which would lose 1/2N's low digits).
  std::vector<float> v(1 << 20);
  for (size_t i = 0; i < v.size(); ++i) v[i] = float(i) / float(v.size());
  const EmpiricalStandardization g(v);
  EXPECT_EQ(g.gaussian_min(), standard_normal_quantile(0.5 / double(v.size())));
  EXPECT_EQ(g.gaussian_max(), -g.gaussian_min());
}

TEST(EmpiricalStandardization, RefusesEmptyAndNonFinite) {
  EXPECT_THROW(EmpiricalStandardization(std::vector<float>{}), Error);
  EXPECT_THROW(EmpiricalStandardization(std::vector<float>{0.1f, std::nanf("")}), Error);
  EXPECT_THROW(EmpiricalStandardization(std::vector<float>{INFINITY}), Error);
}

}  // namespace
}  // namespace mbk
