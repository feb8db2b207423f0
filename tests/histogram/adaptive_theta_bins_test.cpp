// Adaptive theta bins (libbake/histogram/adaptive_theta_bins.h), hard cases first: a flat map (one distinct theta),
// fewer distinct thetas than bins (one bin per value), exactly K distinct values; then two separated clusters, whose
// centres are their means in closed form; and generated and real maps, where the result must be a fixed point of
// Lloyd's step (each centre the mean of the values its bin holds, counted here by brute force), every bin non-empty,
// the same for the same seed, and at the paper's claim's side: a lower k-means cost than uniform bins. Uniform bins
// (the baseline): K equal widths whatever the values, a flat map included, with their RMS error counted by brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "formats/histogram_layout.h"
#include "libbake/gen/generator.h"
#include "libbake/histogram/adaptive_theta_bins.h"
#include "tests/real_normal_maps.h"

namespace mbk {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

std::vector<double> map_thetas(const NormalMap& map) {
  std::vector<double> t;
  for (const Vec3f& n : map.texels) t.push_back(histogram_theta(n.x(), n.y(), n.z()));
  return t;
}

// The bin of theta counted without the library: how many interior edges are <= theta.
size_t brute_force_bin(const std::vector<double>& edges, double theta) {
  size_t bin = 0;
  for (size_t j = 1; j + 1 < edges.size(); ++j) bin += edges[j] <= theta;
  return bin;
}

// Sum of squared distances to the centre of each value's bin (centre = the bin's mean when `means`).
double clustering_cost(const std::vector<double>& values, const std::vector<double>& edges,
                       const std::vector<double>& centres) {
  double cost = 0.0;
  for (double v : values) cost += std::pow(v - centres[brute_force_bin(edges, v)], 2);
  return cost;
}

void expect_valid_edges(const ThetaBins& b) {
  ASSERT_EQ(b.edges.size(), b.centres.size() + 1);
  EXPECT_EQ(b.edges.front(), 0.0);
  EXPECT_EQ(b.edges.back(), kHalfPi);
  for (size_t j = 0; j < b.centres.size(); ++j) {
    EXPECT_LT(b.edges[j], b.edges[j + 1]);
    EXPECT_GE(b.centres[j], b.edges[j]);
    EXPECT_LE(b.centres[j], b.edges[j + 1]);
    if (j > 0) EXPECT_EQ(b.edges[j], 0.5 * (b.centres[j - 1] + b.centres[j]));
  }
}

// Lloyd's fixed point, checked by brute force: every bin holds values, and its centre is their mean.
void expect_lloyd_fixed_point(const std::vector<double>& values, const ThetaBins& b) {
  std::vector<double> sum(b.centres.size(), 0.0), count(b.centres.size(), 0.0);
  for (double v : values) {
    const size_t j = brute_force_bin(b.edges, v);
    sum[j] += v;
    count[j] += 1.0;
  }
  for (size_t j = 0; j < b.centres.size(); ++j) {
    ASSERT_GT(count[j], 0.0) << "empty bin " << j;
    EXPECT_NEAR(b.centres[j], sum[j] / count[j], 1e-12) << "bin " << j;
  }
}

TEST(AdaptiveThetaBins, FlatMapHasOneBinOverTheWholeRange) {
  const ThetaBins b = adaptive_theta_bins(std::vector<double>(100, 0.0), 9, 7);
  EXPECT_EQ(b.centres, std::vector<double>{0.0});
  EXPECT_EQ(b.edges, (std::vector<double>{0.0, kHalfPi}));
  EXPECT_EQ(b.distinct_values, 1u);
  EXPECT_EQ(b.rms_error, 0.0);
}

TEST(AdaptiveThetaBins, FewerDistinctValuesThanBinsGiveOneBinPerValue) {
  std::vector<double> v = {0.7, 0.1, 0.3, 0.1, 0.1, 0.3, 0.1, 0.1};
  const ThetaBins b = adaptive_theta_bins(v, 9, 1);
  EXPECT_EQ(b.centres, (std::vector<double>{0.1, 0.3, 0.7}));
  EXPECT_EQ(b.edges, (std::vector<double>{0.0, 0.5 * (0.1 + 0.3), 0.5 * (0.3 + 0.7), kHalfPi}));
  EXPECT_EQ(b.distinct_values, 3u);
  EXPECT_EQ(b.rms_error, 0.0);
  expect_valid_edges(b);
  // Exactly K distinct values: the same, one bin each; the horizon value pi/2 is a centre on the top edge.
  const ThetaBins k = adaptive_theta_bins({0.0, kHalfPi, 0.4}, 3, 1);
  EXPECT_EQ(k.centres, (std::vector<double>{0.0, 0.4, kHalfPi}));
  expect_valid_edges(k);
  // One value, one bin requested.
  EXPECT_EQ(adaptive_theta_bins({0.2}, 1, 0).edges, (std::vector<double>{0.0, kHalfPi}));
}

TEST(AdaptiveThetaBins, OneBinIsTheMean) {
  const ThetaBins b = adaptive_theta_bins({0.1, 0.2, 0.6}, 1, 3);
  ASSERT_EQ(b.centres.size(), 1u);
  EXPECT_NEAR(b.centres[0], 0.3, 1e-15);
  EXPECT_EQ(b.edges, (std::vector<double>{0.0, kHalfPi}));
}

TEST(AdaptiveThetaBins, TwoSeparatedClustersHaveTheirMeansAsCentres) {
  std::vector<double> v;
  double low = 0.0, high = 0.0;
  for (int i = 0; i < 50; ++i) {
    v.push_back(0.2 + 0.001 * i);
    low += v.back();
    v.push_back(1.2 + 0.002 * i);
    high += v.back();
  }
  for (uint64_t seed : {0ull, 1ull, 0xdeadbeefcafef00dull}) {
    const ThetaBins b = adaptive_theta_bins(v, 2, seed);
    ASSERT_EQ(b.centres.size(), 2u);
    EXPECT_NEAR(b.centres[0], low / 50, 1e-14);
    EXPECT_NEAR(b.centres[1], high / 50, 1e-14);
    expect_valid_edges(b);
  }
}

TEST(AdaptiveThetaBins, GeneratedMapsGiveDeterministicLloydFixedPointsBetterThanUniformBins) {
  for (const char* kind : {"bumps", "scratches", "flakes"}) {
    SCOPED_TRACE(kind);
    const NormalMap map = generate_normal_map(kind, {256, 192}, 1, Progress::silent());
    const std::vector<double> values = map_thetas(map);
    for (uint64_t seed : {1ull, 99ull}) {
      const ThetaBins b = adaptive_theta_bins(values, 9, seed);
      ASSERT_EQ(b.centres.size(), 9u);
      expect_valid_edges(b);
      expect_lloyd_fixed_point(values, b);
      const ThetaBins again = adaptive_theta_bins(values, 9, seed);
      EXPECT_EQ(again.centres, b.centres);
      EXPECT_EQ(again.lloyd_iterations, b.lloyd_iterations);
      EXPECT_NEAR(b.rms_error, std::sqrt(clustering_cost(values, b.edges, b.centres) / values.size()), 1e-12);
      // Uniform bins over [0, pi/2] with each bin's own mean as its centre (the best centres for those bins).
      std::vector<double> uniform_edges;
      for (int j = 0; j <= 9; ++j) uniform_edges.push_back(kHalfPi * j / 9);
      std::vector<double> sum(9, 0.0), count(9, 0.0);
      for (double v : values) {
        sum[brute_force_bin(uniform_edges, v)] += v;
        count[brute_force_bin(uniform_edges, v)] += 1.0;
      }
      std::vector<double> means(9, 0.0);
      for (int j = 0; j < 9; ++j) means[j] = count[j] > 0 ? sum[j] / count[j] : 0.0;
      EXPECT_LT(clustering_cost(values, b.edges, b.centres), clustering_cost(values, uniform_edges, means));
    }
  }
}

TEST(AdaptiveThetaBins, RealMapsGiveLloydFixedPoints) {
  const int maps = test::for_each_real_normal_map([](const NormalMap& map, const std::string& name) {
    SCOPED_TRACE(name);
    const std::vector<double> values = map_thetas(map);
    const ThetaBins b = adaptive_theta_bins(values, 9, 5);
    expect_valid_edges(b);
    expect_lloyd_fixed_point(values, b);
  });
  if (maps == 0) GTEST_SKIP() << "no real normal maps in " << MICROBAKE_REAL_DATA_DIR;
}

TEST(UniformThetaBins, FlatMapKeepsKEqualBins) {
  const ThetaBins b = uniform_theta_bins(std::vector<double>(100, 0.0), 9);
  ASSERT_EQ(b.centres.size(), 9u);
  expect_valid_edges(b);
  for (int j = 0; j <= 9; ++j) EXPECT_NEAR(b.edges[j], kHalfPi * j / 9, 1e-15) << "edge " << j;
  EXPECT_EQ(b.distinct_values, 1u);
  EXPECT_NEAR(b.rms_error, kHalfPi / 18, 1e-15);  // every value at 0, its bin's centre at half a width
}

TEST(UniformThetaBins, OneBinIsTheMiddleOfTheRange) {
  const ThetaBins b = uniform_theta_bins({0.1, 0.2}, 1);
  EXPECT_EQ(b.centres, std::vector<double>{kHalfPi / 2});
  EXPECT_EQ(b.edges, (std::vector<double>{0.0, kHalfPi}));
}

TEST(UniformThetaBins, GeneratedMapsCostMoreThanAdaptiveBinsWithTheRmsErrorCountedByBruteForce) {
  for (const char* kind : {"bumps", "scratches", "flakes"}) {
    SCOPED_TRACE(kind);
    const std::vector<double> values = map_thetas(generate_normal_map(kind, {96, 64}, 3, Progress::silent()));
    const ThetaBins u = uniform_theta_bins(values, 9), a = adaptive_theta_bins(values, 9, 3);
    expect_valid_edges(u);
    EXPECT_NEAR(u.rms_error, std::sqrt(clustering_cost(values, u.edges, u.centres) / values.size()), 1e-12);
    EXPECT_LT(a.rms_error, u.rms_error);
  }
}

}  // namespace
}  // namespace mbk
