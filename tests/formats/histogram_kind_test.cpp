// `validate` on kind 11, `histogram` (formats/kind_histogram.cpp): the hand-built fixture (tests/formats/
// histogram_fixtures.h) is valid, and its footprints read through formats/histogram_layout.h give the texel bins
// it was built from. Baked assets: tests/histogram/bin_count_table_test.cpp. One corrupt fixture per finding is in
// corrupt_fixtures_test.cpp.
#include <gtest/gtest.h>

#include "formats/asset.h"
#include "formats/histogram_layout.h"
#include "formats/validate.h"
#include "tests/formats/histogram_fixtures.h"

namespace mbk {
namespace {

TEST(HistogramKind, HandBuiltFixtureHasNoFindingsAndReadsBackItsTexels) {
  const std::vector<uint8_t> bytes = test::valid_histogram_bytes();
  EXPECT_TRUE(validate_asset(bytes).empty());
  const Asset asset = Asset::parse(bytes, "fixture");
  const HistogramAssetView view = histogram_asset_view(asset);
  EXPECT_EQ(view.bins.theta_bins(), 2u);
  EXPECT_EQ(view.bins.phi_bins, 2u);
  const uint32_t texel_bin[2][3] = {{0, 3, 1}, {2, 2, 0}};
  std::vector<uint64_t> counts(4);
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 3; ++x) {
      footprint_histogram(view.table, x, y, 1, 1, counts);
      for (uint32_t b = 0; b < 4; ++b) EXPECT_EQ(counts[b], b == texel_bin[y][x] ? 1u : 0u);
    }
  footprint_histogram(view.table, 2, 1, 2, 2, counts);  // texels (2, 1), (0, 1), (2, 0), (0, 0): wraps both ways
  EXPECT_EQ(counts, (std::vector<uint64_t>{2, 1, 1, 0}));
}

}  // namespace
}  // namespace mbk
