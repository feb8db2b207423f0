// The MIP pyramid of histograms as a binned-NDF source (libbake/histogram/histogram_pyramid_baseline.h), against
// the exact source it is built from: footprints below 8 x 8 texels are the exact counts; a footprint that is one
// pyramid cell (centred on it, the cell's side) is that cell's exact histogram up to f16 rounding; the pyramid is
// the densest within its byte budget; every prediction is a distribution, also wrapping around the map and on
// non-square, one-texel and one-bin maps; the neural predictor's bytes are what the bench and the effect budget.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "libbake/core/progress.h"
#include "libbake/gen/generator.h"
#include "libbake/histogram/histogram_bake.h"
#include "libbake/histogram/histogram_pyramid_baseline.h"

namespace mbk {
namespace {

struct Fixture {
  BakedHistogram baked;
  HistogramAssetView view() const { return {baked.bins, baked.theta.centres, baked.table()}; }
};

Fixture fixture(const NormalMap& map, HistogramBakeOptions options = {4, 8}) {
  return {bake_histogram(map, options, 3, Progress::silent(), "test")};
}

// Bytes of a pyramid whose level 0 has n x n cells (a square map).
uint64_t square_pyramid_bytes(uint32_t n, uint32_t bins) {
  uint64_t cells = 0;
  for (;; n = (n + 1) / 2) {
    cells += uint64_t(n) * n;
    if (n == 1) break;
  }
  return cells * bins * 2;
}

void expect_distribution(const std::vector<double>& p, const char* what) {
  for (const double v : p) ASSERT_GE(v, 0.0) << what;
  EXPECT_NEAR(std::accumulate(p.begin(), p.end(), 0.0), 1.0, 1e-12) << what;
}

TEST(HistogramPyramidBaseline, FootprintsBelowEightTexelsAreTheExactCounts) {
  const Fixture f = fixture(generate_normal_map("scratches", {40, 24}, 1, Progress::silent()));
  const ExactBinnedNdf exact(f.view());
  const HistogramPyramidBaseline baseline(f.view(), 4096);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-60.0, 60.0), side(0.1, 7.49);
  std::vector<double> p(exact.bins().count()), q(p.size());
  for (int trial = 0; trial < 500; ++trial) {
    const SquareFootprint footprint{coordinate(rng), coordinate(rng), side(rng)};
    ASSERT_LT(square_footprint_texels(footprint).w, 8u);
    exact.footprint_probabilities(footprint, p);
    baseline.footprint_probabilities(footprint, q);
    ASSERT_EQ(p, q) << trial;
  }
}

// A square map whose pyramid has 8 x 8 cells of 8 texels at level 0 (budget exactly that pyramid's bytes), or 64 x
// 64 cells of one texel (any larger budget): footprints centred on a cell of side 8 read that cell alone, on level 0
// or on level 3, and equal the exact histogram of its 64 texels up to the f16 rounding of each probability.
TEST(HistogramPyramidBaseline, AFootprintThatIsOneCellIsItsExactHistogram) {
  const Fixture f = fixture(generate_normal_map("bumps", {64, 64}, 2, Progress::silent()));
  const ExactBinnedNdf exact(f.view());
  const uint32_t bins = exact.bins().count();
  for (const uint64_t budget : {square_pyramid_bytes(8, bins), uint64_t(1) << 40}) {
    const HistogramPyramidBaseline baseline(f.view(), budget);
    EXPECT_LE(baseline.bytes(), budget);
    EXPECT_EQ(baseline.grid().level_width[0], budget == square_pyramid_bytes(8, bins) ? 8u : 64u);
    std::vector<double> p(bins), q(bins);
    for (uint32_t r = 0; r < 8; ++r)
      for (uint32_t c = 0; c < 8; ++c) {
        const SquareFootprint footprint{8.0 * c + 4.0, 8.0 * r + 4.0, 8.0};
        exact.footprint_probabilities(footprint, p);
        baseline.footprint_probabilities(footprint, q);
        for (uint32_t b = 0; b < bins; ++b) ASSERT_NEAR(q[b], p[b], p[b] * 1e-3 + 1e-12) << c << ", " << r;
      }
  }
}

TEST(HistogramPyramidBaseline, IsTheDensestPyramidWithinItsBudget) {
  const Fixture f = fixture(generate_normal_map("leather", {64, 64}, 3, Progress::silent()));
  const uint32_t bins = f.baked.bins.count();
  for (uint32_t n = 1; n < 64; n += 5) {
    const uint64_t budget = square_pyramid_bytes(n + 1, bins) - 1;  // one byte short of n + 1 cells
    const HistogramPyramidBaseline baseline(f.view(), budget);
    EXPECT_EQ(baseline.grid().level_width[0], n);
    EXPECT_EQ(baseline.bytes(), square_pyramid_bytes(n, bins));
  }
  // A budget below one histogram still keeps the whole map's.
  const HistogramPyramidBaseline one(f.view(), 0);
  EXPECT_EQ(one.grid().levels(), 1u);
  EXPECT_EQ(one.bytes(), uint64_t(bins) * 2);
}

TEST(HistogramPyramidBaseline, PredictionsAreDistributionsOnAnyMap) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> coordinate(-1e3, 1e3), side(8.0, 5e3);
  struct Case {
    const char* what;
    NormalMap map;
    HistogramBakeOptions options;
  };
  NormalMap one_texel;
  one_texel.width = one_texel.height = 1;
  one_texel.texels = {Vec3f(0.3f, -0.2f, 0.93f).normalized()};
  const std::vector<Case> cases = {
      {"non-square", generate_normal_map("panels", {72, 20}, 4, Progress::silent()), {9, 32}},
      {"one texel", one_texel, {9, 32}},
      {"one bin", generate_normal_map("flakes", {32, 32}, 5, Progress::silent()), {1, 1}},
  };
  for (const Case& c : cases) {
    const Fixture f = fixture(c.map, c.options);
    const ExactBinnedNdf exact(f.view());
    for (const uint64_t budget : {uint64_t(0), uint64_t(20000), uint64_t(1) << 30}) {
      const HistogramPyramidBaseline baseline(f.view(), budget);
      std::vector<double> q(exact.bins().count()), whole(q.size());
      for (int trial = 0; trial < 200; ++trial) {
        baseline.footprint_probabilities({coordinate(rng), coordinate(rng), side(rng)}, q);
        expect_distribution(q, c.what);
      }
      // The coarsest level is the whole map's histogram: a footprint covering the map reads it.
      exact.footprint_probabilities(whole_map_footprint(c.map.width, c.map.height), whole);
      baseline.footprint_probabilities({0.5 * c.map.width, 0.5 * c.map.height, 1e6}, q);
      for (size_t b = 0; b < q.size(); ++b) EXPECT_NEAR(q[b], whole[b], whole[b] * 1e-3 + 1e-12) << c.what;
    }
  }
}

TEST(HistogramPyramidBaseline, NeuralPredictorBytesAreItsFeaturesAndNetworksInHalfPrecision) {
  const NeuralHistogramShape shape{1024, 1024, 9, 32, 16, kNeuralHistogramHidden};
  // Level 0 is 128 x 128 cells of 8 texels, down to 1 x 1: 21845 cells of 16 features; 10 networks of
  // 17 -> 64 -> 64 -> (9 or 32) weights and biases.
  const uint64_t features = 21845ull * 16;
  const uint64_t hidden = (17 * 64 + 64) + (64 * 64 + 64);
  const uint64_t networks = (hidden + 64 * 9 + 9) + 9 * (hidden + 64 * 32 + 32);
  EXPECT_EQ(neural_predictor_bytes(shape), (features + networks) * 2);
  EXPECT_EQ(neural_predictor_bytes(shape) + uint64_t(1024) * 1024 * 2, shape.model_bytes());
}

}  // namespace
}  // namespace mbk
