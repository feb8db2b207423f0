// The neural histogram ([Shah24] Sec. 4.2; libbake/histogram/neural_*.h): the hand-written gradient of the KL loss
// against central finite differences (network parameters and pyramid features), training bit-for-bit deterministic
// for a seed whatever the thread count, the trained model's held-out KL well below the whole-map histogram's,
// footprints below 8 x 8 counted exactly, the asset's f16 values read back as the bake measured them, and every
// prediction a probability distribution.
#include <Imath/half.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "formats/asset.h"
#include "formats/validate.h"
#include "libbake/core/parallel.h"
#include "libbake/gen/generator.h"
#include "libbake/histogram/bin_count_table.h"
#include "libbake/histogram/histogram_kl.h"
#include "libbake/histogram/neural_binned_ndf.h"
#include "libbake/histogram/neural_histogram_asset.h"
#include "libbake/histogram/neural_histogram_training.h"
#include "tests/histogram/loaded_map.h"

namespace mbk {
namespace {

using test::loaded;

NeuralHistogramBakeOptions quick_options(uint32_t iterations, uint32_t batch) {
  NeuralHistogramBakeOptions options;
  options.bins = {4, 8};
  options.features = 8;
  options.iterations = iterations;
  options.batch = batch;
  return options;
}

// The summed KL of a model over footprints, as chunk_gradient computes it.
double loss(const NeuralHistogramModel& model, const BinnedNdfSource& exact,
            const std::vector<SquareFootprint>& footprints) {
  ChunkGradient g;
  chunk_gradient(model, exact, footprints, g);
  return g.loss;
}

TEST(NeuralHistogram, GradientMatchesFiniteDifferences) {
  const NormalMap map = generate_normal_map("leather", {48, 40}, 3, Progress::silent());
  const BakedHistogram baked = bake_histogram(map, {4, 8}, 7, Progress::silent(), "t");
  const ExactBinnedNdf exact({baked.bins, baked.theta.centres, baked.table()});
  const NeuralHistogramShape shape{48, 40, baked.bins.theta_bins(), 8, 3, 8};
  std::mt19937_64 random(5);
  NeuralHistogramModel model = initial_neural_histogram(shape, exact, random);
  // Larger output weights than the initial ones, so that every layer's gradient is well above rounding.
  for (float& v : model.mlp) v *= 3.0f;
  std::vector<SquareFootprint> footprints;
  for (int i = 0; i < 6; ++i) footprints.push_back(sample_training_footprint(random, 48, 40));
  ChunkGradient g;
  chunk_gradient(model, exact, footprints, g);
  std::vector<float> feature_gradient(model.features.size(), 0.0f);
  add_feature_gradient(g, shape.features, feature_gradient);

  // Central differences at two steps; where they disagree the step crosses a ReLU kink, and the value is skipped.
  int skipped = 0;
  auto check = [&](std::vector<float>& values, const std::vector<float>& analytic, size_t i) {
    const float saved = values[i];
    auto numeric = [&](float h) {
      values[i] = saved + h;
      const double up = loss(model, exact, footprints);
      values[i] = saved - h;
      const double down = loss(model, exact, footprints);
      values[i] = saved;
      return (up - down) / (2.0 * double(h));
    };
    const double coarse = numeric(4e-3f), fine = numeric(2e-3f);
    const double tolerance = 1e-3 + 0.02 * std::abs(fine);
    if (std::abs(coarse - fine) > tolerance) {
      ++skipped;
      return;
    }
    EXPECT_NEAR(analytic[i], fine, tolerance) << "index " << i;
  };
  std::uniform_int_distribution<size_t> mlp_index(0, model.mlp.size() - 1);
  for (int n = 0; n < 60; ++n) check(model.mlp, g.mlp, mlp_index(random));
  int checked = 0;
  for (size_t i = 0; i < model.features.size() && checked < 30; ++i)
    if (feature_gradient[i] != 0.0f) {
      check(model.features, feature_gradient, i);
      ++checked;
    }
  EXPECT_GT(checked, 5);
  EXPECT_LT(skipped, 10);
}

TEST(NeuralHistogram, TrainingIsDeterministicWhateverTheThreadCount) {
  const LoadedNormalMap in = loaded(generate_normal_map("bumps", {40, 32}, 1, Progress::silent()));
  const NeuralHistogramBakeOptions options = quick_options(20, 80);  // 3 chunks, the last one short
  auto bytes = [&](int threads, uint64_t seed) {
    set_thread_count(threads);
    NeuralHistogramBakeOptions o = options;
    o.seed = seed;
    return bake_neural_histogram_asset(in, o, Progress::silent(), "t").serialize();
  };
  const std::vector<uint8_t> one = bytes(1, 1), two = bytes(2, 1), again = bytes(2, 1), other = bytes(2, 2);
  set_thread_count(0);
  EXPECT_EQ(one, two);
  EXPECT_EQ(two, again);
  EXPECT_NE(two, other);
}

TEST(NeuralHistogram, TrainedModelBeatsTheWholeMapHistogram) {
  const NormalMap map = generate_normal_map("leather", {128, 128}, 2, Progress::silent());
  NeuralHistogramBakeOptions options = quick_options(1600, 128);
  options.bins = {9, 32};
  options.features = 16;
  const BakedNeuralHistogram baked = bake_neural_histogram(map, options, 3, Progress::silent(), "t");
  EXPECT_GT(baked.marginal_kl, 0.0);
  EXPECT_LT(baked.held_out_kl, 0.7 * baked.marginal_kl)
      << "held-out KL " << baked.held_out_kl << ", whole-map histogram " << baked.marginal_kl;
  EXPECT_LT(baked.training_loss, baked.marginal_kl);
}

TEST(NeuralHistogram, AssetReadsBackWhatTheBakeMeasuredAndCountsSmallFootprints) {
  const LoadedNormalMap in = loaded(generate_normal_map("scratches", {37, 29}, 4, Progress::silent()));
  const NeuralHistogramBakeOptions options = quick_options(30, 64);
  const uint64_t seed = histogram_seed(in.record.content_hash);
  BakedNeuralHistogram baked = bake_neural_histogram(in.map, options, seed, Progress::silent(), "t");
  const NeuralHistogramModel model = baked.model;
  for (float v : model.features) ASSERT_EQ(v, float(Imath::half(v)));  // rounded to f16
  for (float v : model.mlp) ASSERT_EQ(v, float(Imath::half(v)));
  const std::vector<uint8_t> bytes = neural_histogram_asset_writer(in, options, seed, std::move(baked)).serialize();
  EXPECT_TRUE(validate_asset(bytes).empty());
  const Asset asset = Asset::parse(bytes, "mem");
  const std::unique_ptr<BinnedNdfSource> source = open_neural_histogram(asset);
  ASSERT_EQ(source->width(), 37u);
  ASSERT_EQ(source->height(), 29u);

  const BakedHistogram exact_baked = bake_histogram(in.map, options.bins, seed, Progress::silent(), "t");
  const ExactBinnedNdf exact({exact_baked.bins, exact_baked.theta.centres, exact_baked.table()});
  EXPECT_EQ(source->bins().theta_edges, exact.bins().theta_edges);
  const uint32_t B = exact.bins().count();
  std::vector<double> p(B), q(B), r(B);
  std::mt19937_64 random(9);
  std::uniform_real_distribution<double> coordinate(-50.0, 90.0), small(0.0, 7.49), large(7.5, 200.0);
  for (int trial = 0; trial < 200; ++trial) {
    const SquareFootprint f{coordinate(random), coordinate(random), small(random)};
    source->footprint_probabilities(f, q);
    exact.footprint_probabilities(f, p);
    for (uint32_t b = 0; b < B; ++b) ASSERT_NEAR(q[b], p[b], 1e-12) << "side " << f.side << " bin " << b;
  }
  for (int trial = 0; trial < 100; ++trial) {
    const SquareFootprint f{coordinate(random), coordinate(random), large(random)};
    source->footprint_probabilities(f, q);
    model.probabilities(f.x, f.y, double(square_footprint_texels(f).w), r);
    double sum = 0.0;
    for (uint32_t b = 0; b < B; ++b) {
      ASSERT_EQ(q[b], r[b]);
      ASSERT_GE(q[b], 0.0);
      sum += q[b];
    }
    ASSERT_NEAR(sum, 1.0, 1e-5);
  }
}

TEST(NeuralHistogram, PyramidLevelsHalveDownToOneTexel) {
  const NeuralHistogramShape shape{1024, 200, 9, 32, 16, 64};
  EXPECT_EQ(shape.level_width(0), 128u);
  EXPECT_EQ(shape.level_height(0), 25u);
  EXPECT_EQ(shape.levels(), 8u);  // 128 -> 1 in 7 halvings
  EXPECT_EQ(shape.level_height(5), 1u);
  EXPECT_EQ(shape.level_width(7), 1u);
  const NeuralHistogramShape one{1, 1, 1, 1, 4, 8};
  EXPECT_EQ(one.levels(), 1u);
  EXPECT_EQ(one.pyramid_texels(), 1u);
  // Trilinear weights sum to 1, also past the coarsest level.
  for (const double side : {8.0, 11.0, 100.0, 5000.0, 1e7}) {
    const PyramidLookup l = pyramid_lookup(neural_pyramid_grid(shape), 1000.5, -3.25, side);
    double sum = 0.0;
    for (float w : l.weight) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-6) << side;
    for (uint64_t t : l.texel) EXPECT_LT(t, shape.pyramid_texels());
  }
}

}  // namespace
}  // namespace mbk
