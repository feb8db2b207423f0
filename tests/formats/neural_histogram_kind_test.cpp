// `validate` on kind 12, `neural_histogram` (formats/kind_neural_histogram.cpp): the hand-built fixture
// (tests/formats/neural_histogram_fixtures.h) is valid, footprints below 8 x 8 read its texel bins, and a larger
// footprint's probabilities equal the networks of formats/SPEC.md "Kind 12" evaluated here with plain loops from the
// f16 values. Baked assets: tests/histogram/neural_histogram_test.cpp. One corrupt fixture per finding is in
// corrupt_fixtures_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "formats/asset.h"
#include "formats/validate.h"
#include "libbake/histogram/neural_binned_ndf.h"
#include "tests/formats/neural_histogram_fixtures.h"

namespace mbk {
namespace {

// Network m of the fixture (in 3, hidden 3, out 2) on `input`, then log-softmax, by the spec's layout.
std::vector<double> log_softmax_of_network(const test::NeuralHistogramFixture& f, int m, const double input[3]) {
  const int in = 3, hidden = 3, out = 2, size = 32;
  auto p = [&](int i) { return double(float(f.mlp[size_t(m * size + i)])); };
  double a1[3], a2[3];
  for (int h = 0; h < hidden; ++h) {
    double z = p(hidden * in + h);  // b1
    for (int i = 0; i < in; ++i) z += p(h * in + i) * input[i];
    a1[h] = std::max(z, 0.0);
  }
  const int w2 = hidden * in + hidden, b2 = w2 + hidden * hidden, w3 = b2 + hidden, b3 = w3 + out * hidden;
  for (int h = 0; h < hidden; ++h) {
    double z = p(b2 + h);
    for (int i = 0; i < hidden; ++i) z += p(w2 + h * hidden + i) * a1[i];
    a2[h] = std::max(z, 0.0);
  }
  std::vector<double> logits(out);
  for (int o = 0; o < out; ++o) {
    logits[o] = p(b3 + o);
    for (int i = 0; i < hidden; ++i) logits[o] += p(w3 + o * hidden + i) * a2[i];
  }
  const double norm = std::log(std::exp(logits[0]) + std::exp(logits[1]));
  for (double& l : logits) l -= norm;
  return logits;
}

TEST(NeuralHistogramKind, HandBuiltFixtureIsValidAndPredictsAsTheSpecSays) {
  const test::NeuralHistogramFixture fixture;
  const std::vector<uint8_t> bytes = fixture.bytes();
  EXPECT_TRUE(validate_asset(bytes).empty());
  const Asset asset = Asset::parse(bytes, "fixture");
  const std::unique_ptr<BinnedNdfSource> source = open_neural_histogram(asset);
  EXPECT_EQ(source->bins().theta_bins(), 2u);
  EXPECT_EQ(source->bins().phi_bins, 2u);
  std::vector<double> p(4);
  // One texel: its bin.
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 3; ++x) {
      source->footprint_probabilities({x + 0.5, y + 0.5, 1.0}, p);
      for (uint32_t b = 0; b < 4; ++b) EXPECT_EQ(p[b], b == fixture.texel_bins[y * 3 + x] ? 1.0 : 0.0);
    }
  // 2 x 2 at texel (2, 1), wrapping both ways: texels (2, 1), (0, 1), (2, 0), (0, 0) -> bins 0, 2, 1, 0.
  source->footprint_probabilities({3.0, 2.0, 2.0}, p);
  EXPECT_EQ(p, (std::vector<double>{0.5, 0.25, 0.25, 0.0}));
  // 16 x 16: the one pyramid texel's features and log2(16 / 8) / 8, through the networks.
  const double input[3] = {0.25, -0.5, 1.0 / 8.0};
  const std::vector<double> theta = log_softmax_of_network(fixture, 0, input);
  source->footprint_probabilities({1.0, 1.0, 16.0}, p);
  for (int j = 0; j < 2; ++j) {
    const std::vector<double> phi = log_softmax_of_network(fixture, 1 + j, input);
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(p[size_t(j * 2 + i)], std::exp(theta[j] + phi[i]), 1e-6);
  }
}

}  // namespace
}  // namespace mbk
