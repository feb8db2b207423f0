// Test fixtures for the `histogram` kind: a small valid 3 x 2 asset built by hand from formats/SPEC.md "Kind 11:
// histogram" (two theta bins with centres 0.2 and 0.5, two phi bins, texel bins chosen here and their integral
// images summed by brute force, independently of the bake), and readable corruptions of it, one per histogram
// finding (tests/formats/corrupt_fixtures_test.cpp). A corruption edits the arrays before they are written, so the
// checksums are right and only the invariant is broken.
#pragma once

#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

#include "formats/asset_writer.h"

namespace mbk::test {

struct HistogramFixture {
  nlohmann::json parameters = {{"width", 3},      {"height", 2},   {"method", "exact"},
                               {"theta_bins", 2}, {"phi_bins", 2}, {"theta_bins_requested", 9},
                               {"seed", 1}};
  std::vector<double> theta_centres = {0.2, 0.5};
  std::vector<double> theta_edges = {0.0, 0.5 * (0.2 + 0.5), std::numbers::pi / 2};
  std::vector<double> phi_edges = {0.0, std::numbers::pi, 2.0 * std::numbers::pi};
  std::vector<uint32_t> counts;  // [3, 4, 4]

  HistogramFixture() {
    const uint32_t W = 3, H = 2, B = 4;
    const uint32_t texel_bin[H][W] = {{0, 3, 1}, {2, 2, 0}};
    for (uint32_t Y = 0; Y <= H; ++Y)
      for (uint32_t X = 0; X <= W; ++X)
        for (uint32_t b = 0; b < B; ++b) {
          uint32_t n = 0;
          for (uint32_t y = 0; y < Y; ++y)
            for (uint32_t x = 0; x < X; ++x) n += texel_bin[y][x] == b;
          counts.push_back(n);
        }
  }
  uint32_t& count(uint32_t Y, uint32_t X, uint32_t b) { return counts[(Y * 4 + X) * 4 + b]; }

  std::vector<uint8_t> bytes() const {
    nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                           {"parameters", parameters},
                           {"conventions", nlohmann::json::object()},
                           {"statistics", nlohmann::json::object()}};
    AssetWriter w("histogram", meta);
    w.add<double>("theta_edges", {theta_edges.size()}, theta_edges);
    w.add<double>("theta_centres", {theta_centres.size()}, theta_centres);
    w.add<double>("phi_edges", {phi_edges.size()}, phi_edges);
    w.add<uint32_t>("bin_counts", {3, 4, 4}, counts);
    return w.serialize();
  }
};

inline std::vector<uint8_t> valid_histogram_bytes() { return HistogramFixture().bytes(); }

// The valid fixture after `change`.
inline std::vector<uint8_t> histogram_with(const std::function<void(HistogramFixture&)>& change) {
  HistogramFixture f;
  change(f);
  return f.bytes();
}

}  // namespace mbk::test
