// The lookup convention of standardization tables (formats/lut_lookup.h, formats/lut_layout.h): samples at
// lo + j (hi - lo) / (size - 1) come back exactly, linear in between with the interval's slope as derivative, and
// every lookup outside [lo, hi] (or NaN, or infinite) clamps to an end sample with derivative 0.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "formats/lut_layout.h"
#include "formats/lut_lookup.h"

namespace mbk {
namespace {

struct Table {
  std::vector<float> values, slopes;
  LutTableView view(double lo, double hi) const { return {lo, hi, values, slopes}; }
};

Table make_table(std::vector<float> values, double lo, double hi) {
  Table t{std::move(values), {}};
  for (size_t j = 0; j + 1 < t.values.size(); ++j)
    t.slopes.push_back(float(lut_interval_slope(lo, hi, uint32_t(t.values.size()), t.values[j], t.values[j + 1])));
  return t;
}

TEST(LutLookup, SamplesComeBackExactly) {
  const Table t = make_table({-2.0f, -1.0f, 0.5f, 0.75f, 3.0f}, -1.0, 1.0);
  for (uint32_t j = 0; j < 5; ++j)
    EXPECT_EQ(lut_lookup(t.view(-1.0, 1.0), lut_sample_position(-1.0, 1.0, 5, j)).value, t.values[j]) << j;
}

TEST(LutLookup, LinearBetweenSamplesWithTheIntervalSlope) {
  const Table t = make_table({-2.0f, -1.0f, 0.5f, 0.75f, 3.0f}, -1.0, 1.0);  // samples at -1, -0.5, 0, 0.5, 1
  const LutSample s = lut_lookup(t.view(-1.0, 1.0), -0.25);
  EXPECT_DOUBLE_EQ(s.value, -0.25);
  EXPECT_DOUBLE_EQ(s.derivative, 1.5 / 0.5);
  // On [s_j, s_{j+1}) the derivative is interval j's slope; at hi, the last interval's.
  EXPECT_DOUBLE_EQ(lut_lookup(t.view(-1.0, 1.0), -1.0).derivative, 2.0);
  EXPECT_DOUBLE_EQ(lut_lookup(t.view(-1.0, 1.0), 0.75).derivative, 4.5);
  EXPECT_DOUBLE_EQ(lut_lookup(t.view(-1.0, 1.0), 1.0).derivative, 4.5);
  EXPECT_DOUBLE_EQ(lut_lookup(t.view(-1.0, 1.0), 1.0).value, 3.0);
}

TEST(LutLookup, EveryLookupClampsOutsideTheDomain) {
  const Table t = make_table({-2.0f, -1.0f, 0.5f, 0.75f, 3.0f}, -1.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  for (double x : {-1.0000001, -7.0, -1e300, -inf, std::nan("")}) {
    const LutSample s = lut_lookup(t.view(-1.0, 1.0), x);
    EXPECT_EQ(s.value, -2.0) << x;
    EXPECT_EQ(s.derivative, 0.0) << x;
  }
  for (double x : {1.0000001, 7.0, 1e300, inf}) {
    const LutSample s = lut_lookup(t.view(-1.0, 1.0), x);
    EXPECT_EQ(s.value, 3.0) << x;
    EXPECT_EQ(s.derivative, 0.0) << x;
  }
}

TEST(LutLookup, NonFiniteDomainsNeverReadOutOfBounds) {
  // validate refuses such tables; a lookup in one must still stay inside the arrays (ASan would catch it).
  const Table t = make_table({-2.0f, -1.0f, 0.5f}, -1.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  for (const auto& [lo, hi] : {std::pair{-inf, 1.0}, {-1.0, inf}, {-inf, inf}, {nan, 1.0}, {-1.0, nan}, {1.0, -1.0}})
    for (double x : {-inf, -1.0, 0.0, 0.5, 1.0, inf, nan}) {
      const LutSample s = lut_lookup(t.view(lo, hi), x);
      EXPECT_TRUE(s.value >= -2.0 && s.value <= 0.5) << lo << " " << hi << " " << x;
    }
}

TEST(LutLookup, EmptyDomainIsAConstant) {
  const Table t = make_table({0.25f, 0.25f, 0.25f}, 0.5, 0.5);
  for (double x : {0.0, 0.5, 1.0}) {
    EXPECT_EQ(lut_lookup(t.view(0.5, 0.5), x).value, 0.25f);
    EXPECT_EQ(lut_lookup(t.view(0.5, 0.5), x).derivative, 0.0);
  }
}

TEST(LutLookup, TwoSamplesAndManySamples) {
  const Table two = make_table({1.0f, 3.0f}, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(lut_lookup(two.view(0.0, 1.0), 0.25).value, 1.5);
  EXPECT_DOUBLE_EQ(lut_lookup(two.view(0.0, 1.0), 0.25).derivative, 2.0);
  // 65536 samples of x^3 on [-1, 1]: the index arithmetic stays in range at both ends and in between.
  std::vector<float> cubic(65536);
  for (uint32_t j = 0; j < cubic.size(); ++j) cubic[j] = float(std::pow(lut_sample_position(-1, 1, 65536, j), 3));
  const Table many = make_table(cubic, -1.0, 1.0);
  for (double x = -1.0; x <= 1.0; x += 1.0 / 4096) {
    const LutSample s = lut_lookup(many.view(-1.0, 1.0), x);
    ASSERT_NEAR(s.value, x * x * x, 1e-6) << x;
    // Float samples 3e-5 apart: each slope carries float rounding / step ~ 4e-3.
    ASSERT_NEAR(s.derivative, 3 * x * x, 1e-2) << x;
  }
}

}  // namespace
}  // namespace mbk
