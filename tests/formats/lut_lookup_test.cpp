// The lookup convention of standardization knots (formats/lut_lookup.h): knots come back exactly, values are
// linear in between with the segment's slope as derivative, every lookup outside the knots (or NaN, or infinite)
// clamps to an end with derivative 0, and the cell index finds the same segment as a plain binary search, on
// evenly and very unevenly spaced knots (a cluster of 1000 knots within a few ulps, as an atom makes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "formats/lut_lookup.h"

namespace mbk {
namespace {

TEST(LutLookup, KnotsComeBackExactly) {
  const std::vector<float> k = {-1.0f, -0.5f, 0.25f, 0.5f, 1.0f}, v = {-2.0f, -1.0f, 0.5f, 0.75f, 3.0f};
  const KnotInterpolant f(k, v);
  for (size_t i = 0; i < k.size(); ++i) EXPECT_EQ(f(k[i]).value, v[i]) << i;
}

TEST(LutLookup, LinearBetweenKnotsWithTheSegmentsSlope) {
  const std::vector<float> k = {-1.0f, -0.5f, 0.25f, 0.5f, 1.0f}, v = {-2.0f, -1.0f, 0.5f, 0.75f, 3.0f};
  const KnotInterpolant f(k, v);
  EXPECT_DOUBLE_EQ(f(-0.75).value, -1.5);
  EXPECT_DOUBLE_EQ(f(-0.75).derivative, 2.0);
  EXPECT_DOUBLE_EQ(f(-1.0).derivative, 2.0);  // at a knot: the segment starting there
  EXPECT_DOUBLE_EQ(f(0.25).derivative, 1.0);
  EXPECT_DOUBLE_EQ(f(1.0).derivative, 4.5);  // at the last knot: the last segment
  EXPECT_DOUBLE_EQ(f(1.0).value, 3.0);
}

TEST(LutLookup, ClampsOutsideTheKnots) {
  const std::vector<float> k = {0.0f, 1.0f, 2.0f}, v = {5.0f, 6.0f, 8.0f};
  const KnotInterpolant f(k, v);
  for (double x : {-1.0, -std::numeric_limits<double>::infinity(), std::nan("")}) {
    EXPECT_EQ(f(x).value, 5.0) << x;
    EXPECT_EQ(f(x).derivative, 0.0) << x;
  }
  for (double x : {2.0000001, 1e300, std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(f(x).value, 8.0) << x;
    EXPECT_EQ(f(x).derivative, 0.0) << x;
  }
}

TEST(LutLookup, OneKnotIsAConstant) {
  const std::vector<float> k = {0.25f}, v = {0.0f};
  const KnotInterpolant f(k, v);
  for (double x : {-1.0, 0.25, 3.0, std::nan("")}) {
    EXPECT_EQ(f(x).value, 0.0);
    EXPECT_EQ(f(x).derivative, 0.0);
  }
}

TEST(LutLookup, CellIndexFindsTheSegmentABinarySearchFinds) {
  // Even knots, then a cluster of 1000 knots within ~1000 ulps of 0.3 between sparse ones (an atom's rise).
  std::vector<float> k, v;
  for (int i = 0; i <= 100; ++i) k.push_back(-1.0f + 0.01f * float(i));
  float x = 0.3f;
  for (int i = 0; i < 1000; ++i) k.push_back(x = std::nextafter(x, 1.0f));
  for (int i = 1; i <= 50; ++i) k.push_back(0.31f + 0.01f * float(i));
  std::sort(k.begin(), k.end());
  k.erase(std::unique(k.begin(), k.end()), k.end());
  for (size_t i = 0; i < k.size(); ++i) v.push_back(float(i) * 0.01f);
  const KnotInterpolant f(k, v);
  for (int q = 0; q <= 200000; ++q) {
    const double t = -1.0 + (double(k.back()) + 1.0) * q / 200000.0;
    const double probe = q % 2 ? t : double(k[size_t(q / 2) % k.size()]);  // also every knot exactly
    size_t i = size_t(std::upper_bound(k.begin(), k.end(), probe, [](double a, float b) { return a < b; }) - k.begin());
    i = std::min(i == 0 ? 0 : i - 1, k.size() - 2);
    const double expected = v[i] + (probe - k[i]) * ((double(v[i + 1]) - v[i]) / (double(k[i + 1]) - k[i]));
    ASSERT_EQ(f(probe).value, expected) << probe;
  }
}

TEST(LutLookup, ForwardAndInverseThroughTheSameKnotsAreInverses) {
  std::vector<float> k, v;
  for (int i = 0; i < 500; ++i) k.push_back(std::ldexp(float(i), -9)), v.push_back(std::tanh(float(i) / 100.0f));
  const KnotInterpolant forward(k, v), inverse(v, k);
  for (int q = 0; q <= 10000; ++q) {
    const double x = k.back() * q / 10000.0;
    ASSERT_NEAR(inverse(forward(x).value).value, x, 1e-12) << x;
  }
}

}  // namespace
}  // namespace mbk
