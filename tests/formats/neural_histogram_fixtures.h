// Test fixtures for the `neural_histogram` kind: a small valid 3 x 2 asset built by hand from formats/SPEC.md
// "Kind 12: neural_histogram" (two theta bins with centres 0.2 and 0.5, two phi bins, F = 2 features, hidden width
// 3, so one 1 x 1 pyramid level and three networks of 32 parameters), and readable corruptions of it, one per
// finding (tests/formats/corrupt_fixtures_test.cpp). A corruption edits the arrays before they are written, so the
// checksums are right and only the invariant is broken.
#pragma once

#include <Imath/half.h>

#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

#include "formats/asset_writer.h"

namespace mbk::test {

struct NeuralHistogramFixture {
  nlohmann::json parameters = {{"width", 3},    {"height", 2},       {"method", "neural"},        {"theta_bins", 2},
                               {"phi_bins", 2}, {"seed", 1},         {"theta_bins_requested", 9}, {"features", 2},
                               {"hidden", 3},   {"levels", 1},       {"min_footprint", 8},        {"iterations", 10},
                               {"batch", 4},    {"training_seed", 1}};
  std::vector<double> theta_centres = {0.2, 0.5};
  std::vector<double> theta_edges = {0.0, 0.5 * (0.2 + 0.5), std::numbers::pi / 2};
  std::vector<uint16_t> texel_bins = {0, 3, 1, 2, 2, 0};                         // [2, 3]
  std::vector<Imath::half> features = {Imath::half(0.25f), Imath::half(-0.5f)};  // [1, 2]
  std::vector<Imath::half> mlp;                                                  // [96]

  NeuralHistogramFixture() {
    for (int i = 0; i < 96; ++i) mlp.push_back(Imath::half(0.125f * float((i * 7) % 11) - 0.5f));
  }

  std::vector<uint8_t> bytes() const {
    nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                           {"parameters", parameters},
                           {"conventions", nlohmann::json::object()},
                           {"statistics", nlohmann::json::object()}};
    AssetWriter w("neural_histogram", meta);
    w.add<double>("theta_edges", {theta_edges.size()}, theta_edges);
    w.add<double>("theta_centres", {theta_centres.size()}, theta_centres);
    w.add<uint16_t>("texel_bins", {2, 3}, texel_bins);
    w.add<Imath::half>("features", {features.size() / 2, 2}, features);
    w.add<Imath::half>("mlp", {mlp.size()}, mlp);
    return w.serialize();
  }
};

inline std::vector<uint8_t> valid_neural_histogram_bytes() { return NeuralHistogramFixture().bytes(); }

// The valid fixture after `change`.
inline std::vector<uint8_t> neural_histogram_with(const std::function<void(NeuralHistogramFixture&)>& change) {
  NeuralHistogramFixture f;
  change(f);
  return f.bytes();
}

}  // namespace mbk::test
