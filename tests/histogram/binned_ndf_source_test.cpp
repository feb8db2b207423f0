// Square footprints in whole texels and the exact binned-NDF source (libbake/histogram/binned_ndf_source.h): the
// source's probabilities equal brute-force counting of the texels' bins over random squares anywhere on the tiled
// map (wrapping, larger than the map); rounding of centres and sides; non-finite sides (NaN one texel, +inf the
// largest square: the grazing footprint, whose histogram is the whole map's).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "formats/asset.h"
#include "libbake/histogram/binned_ndf_source.h"
#include "libbake/histogram/histogram_asset.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

TEST(BinnedNdfSource, SquaresAreRoundedToWholeTexels) {
  const FootprintTexels one = square_footprint_texels({3.7, 5.2, 0.3});
  EXPECT_EQ(one.x0, 3);
  EXPECT_EQ(one.row0, 5);
  EXPECT_EQ(one.w, 1u);
  const FootprintTexels two = square_footprint_texels({4.0, -0.9, 2.2});  // texels 3, 4 and rows -2, -1
  EXPECT_EQ(two.x0, 3);
  EXPECT_EQ(two.row0, -2);
  EXPECT_EQ(two.w, 2u);
  EXPECT_EQ(square_footprint_texels({0, 0, std::numeric_limits<double>::quiet_NaN()}).w, 1u);
  EXPECT_EQ(square_footprint_texels({0, 0, std::numeric_limits<double>::infinity()}).w, uint64_t(1) << 24);
}

TEST(BinnedNdfSource, ExactSourceCountsTheTexelsOfTheSquare) {
  test::ScratchDir dir("binned_ndf_source");
  const uint32_t W = 13, H = 9;
  LoadedNormalMap loaded;
  loaded.map.width = W;
  loaded.map.height = H;
  std::mt19937_64 rng(11);
  std::normal_distribution<float> normal;
  for (uint32_t i = 0; i < W * H; ++i)
    loaded.map.texels.push_back(Vec3f(0.5f * normal(rng), 0.5f * normal(rng), 1.0f).normalized());
  const HistogramBakeOptions options{4, 8};
  histogram_asset_writer(loaded, options, 1, bake_histogram(loaded.map, options, 1, Progress::silent(), "test"))
      .write(dir / "h.mbk");
  const Asset asset = Asset::open(dir / "h.mbk");
  const ExactBinnedNdf source(histogram_asset_view(asset));
  const HistogramBins& bins = source.bins();
  std::vector<uint32_t> texel_bin;
  for (const Vec3f& n : loaded.map.texels) texel_bin.push_back(bins.bin_of(n.x(), n.y(), n.z()));

  std::uniform_real_distribution<double> coordinate(-40.0, 40.0), side(0.2, 30.0);
  std::vector<double> p(bins.count());
  for (int trial = 0; trial < 300; ++trial) {
    const SquareFootprint f{coordinate(rng), coordinate(rng), side(rng)};
    source.footprint_probabilities(f, p);
    const FootprintTexels t = square_footprint_texels(f);
    std::vector<double> expected(bins.count(), 0.0);
    for (uint64_t r = 0; r < t.w; ++r)
      for (uint64_t c = 0; c < t.w; ++c) {
        const int64_t x = ((t.x0 + int64_t(c)) % W + W) % W, y = ((t.row0 + int64_t(r)) % H + H) % H;
        expected[texel_bin[size_t(y * W + x)]] += 1.0 / double(t.w * t.w);
      }
    for (uint32_t b = 0; b < bins.count(); ++b) ASSERT_NEAR(p[b], expected[b], 1e-12) << trial << " bin " << b;
  }
  // A grazing footprint (infinite side) sees the whole map: within 16384 / 2^24 of its histogram.
  source.footprint_probabilities({2.5, 2.5, std::numeric_limits<double>::infinity()}, p);
  std::vector<double> whole(bins.count(), 0.0);
  for (const uint32_t b : texel_bin) whole[b] += 1.0 / double(W * H);
  for (uint32_t b = 0; b < bins.count(); ++b) EXPECT_NEAR(p[b], whole[b], 1e-3);
}

}  // namespace
}  // namespace mbk
