// The exact binned P-NDF (libbake/histogram/bin_count_table.h read through formats/histogram_layout.h): the counts
// of every footprint against brute-force counting over its texels, on 1,000+ random footprints per map (origins
// anywhere, so footprints wrap around both sides; sizes up to twice the map's, counting texels as often as the
// footprint covers them), for a 1 x 1 map, thin and non-square maps, generated maps and a realistic 256 x 256 one;
// normals exactly on a bin edge; the size limit; z < 0 texels refused or repaired as the decoder does; the asset
// written, read back and validated; and the same bytes whatever the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "formats/asset.h"
#include "formats/error.h"
#include "formats/validate.h"
#include "libbake/core/hash.h"
#include "libbake/core/parallel.h"
#include "libbake/gen/generator.h"
#include "libbake/histogram/bin_count_table.h"
#include "libbake/histogram/histogram_asset.h"
#include "tests/histogram/loaded_map.h"

namespace mbk {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

NormalMap random_map(uint32_t w, uint32_t h, uint32_t seed) {
  NormalMap m{w, h, {}};
  for (uint32_t i = 0; i < w * h; ++i) {
    const double x = 1.6 * unit_from_hash(hash3(seed, i, 1)) - 0.8, y = 1.6 * unit_from_hash(hash3(seed, i, 2)) - 0.8;
    m.texels.push_back(
        Vec3f(float(x), float(y), float(std::sqrt(std::max(0.0, 1.0 - x * x - y * y)) + 0.1)).normalized());
  }
  return m;
}

// Counts the footprint's texels one by one on the repeated map.
std::vector<uint64_t> brute_force_counts(const std::vector<uint32_t>& texel_bin, uint32_t W, uint32_t H, uint32_t B,
                                         int64_t x0, int64_t y0, uint64_t w, uint64_t h) {
  std::vector<uint64_t> counts(B, 0);
  for (uint64_t dy = 0; dy < h; ++dy) {
    const int64_t row = (((y0 + int64_t(dy)) % H) + H) % H;
    for (uint64_t dx = 0; dx < w; ++dx) {
      const int64_t col = (((x0 + int64_t(dx)) % W) + W) % W;
      ++counts[texel_bin[size_t(row) * W + size_t(col)]];
    }
  }
  return counts;
}

// 1,000 random footprints plus the whole map and the corner-straddling ones, against brute force.
void expect_footprints_match_brute_force(const NormalMap& map, uint32_t theta_bins, uint32_t phi_bins) {
  const BakedHistogram baked = bake_histogram(map, {theta_bins, phi_bins}, 42, Progress::silent(), "test");
  const std::vector<uint32_t> bins = texel_bins(map, baked.bins);
  const uint32_t W = map.width, H = map.height, B = baked.bins.count();
  struct Footprint {
    int64_t x0, y0;
    uint64_t w, h;
  };
  std::vector<Footprint> footprints = {
      {0, 0, W, H}, {int64_t(W) - 1, int64_t(H) - 1, 2, 2}, {-1, -1, 1, 1}, {0, 0, 2 * uint64_t(W) + 1, 1}};
  for (uint32_t k = 0; k < 1000; ++k) {
    auto u = [&](uint32_t salt) { return unit_from_hash(hash4(W, H, k, salt)); };
    const uint64_t limit_w = k % 10 == 0 ? 2 * W : W, limit_h = k % 10 == 0 ? 2 * H : H;
    const uint64_t w = 1 + uint64_t(u(3) * limit_w), h = 1 + uint64_t(u(4) * limit_h);
    footprints.push_back({int64_t(u(1) * 6 * W) - 3 * int64_t(W), int64_t(u(2) * 6 * H) - 3 * int64_t(H), w, h});
  }
  std::vector<uint64_t> counts(B);
  uint32_t wrapped = 0;
  for (const Footprint& f : footprints) {
    footprint_histogram(baked.table(), f.x0, f.y0, f.w, f.h, counts);
    ASSERT_EQ(counts, brute_force_counts(bins, W, H, B, f.x0, f.y0, f.w, f.h))
        << W << "x" << H << " footprint (" << f.x0 << ", " << f.y0 << ") " << f.w << "x" << f.h;
    const int64_t x = ((f.x0 % W) + W) % W, y = ((f.y0 % H) + H) % H;
    wrapped += uint64_t(x) + f.w > W || uint64_t(y) + f.h > H;
  }
  EXPECT_GT(wrapped, 50u);  // the wrap-around path is exercised (on a 1 x 1 map only footprints beyond it wrap)
}

TEST(BinCountTable, OneTexelMap) {
  NormalMap map{1, 1, {Vec3f(0.6f, 0.0f, 0.8f)}};
  const BakedHistogram baked = bake_histogram(map, {9, 32}, 1, Progress::silent(), "test");
  EXPECT_EQ(baked.bins.theta_bins(), 1u);  // one distinct theta
  EXPECT_EQ(baked.counts.size(), 2u * 2 * 32);
  std::vector<uint64_t> counts(32);
  footprint_histogram(baked.table(), 5, -7, 3, 2, counts);  // six copies of the one texel
  for (uint32_t b = 0; b < 32; ++b) EXPECT_EQ(counts[b], b == 0 ? 6u : 0u) << b;
  expect_footprints_match_brute_force(map, 9, 32);
}

TEST(BinCountTable, FlatMapAtThePoleIsAllInBinZero) {
  NormalMap map{5, 3, std::vector<Vec3f>(15, Vec3f(0, 0, 1))};
  const BakedHistogram baked = bake_histogram(map, {9, 32}, 1, Progress::silent(), "test");
  EXPECT_EQ(baked.bins.theta_bins(), 1u);
  std::vector<uint64_t> counts(32);
  footprint_histogram(baked.table(), 0, 0, 5, 3, counts);
  EXPECT_EQ(counts[0], 15u);
  for (uint32_t b = 1; b < 32; ++b) EXPECT_EQ(counts[b], 0u);
}

TEST(BinCountTable, ThinAndNonSquareRandomMapsMatchBruteForce) {
  for (const auto& [w, h] : std::vector<std::pair<uint32_t, uint32_t>>{{1, 7}, {7, 1}, {5, 3}, {13, 29}, {64, 17}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    expect_footprints_match_brute_force(random_map(w, h, w * 31 + h), 9, 32);
    expect_footprints_match_brute_force(random_map(w, h, w * 31 + h), 3, 5);
  }
}

TEST(BinCountTable, GeneratedMapsMatchBruteForce) {
  for (const char* kind : {"scratches", "bumps"}) {
    SCOPED_TRACE(kind);
    expect_footprints_match_brute_force(generate_normal_map(kind, {96, 64}, 3, Progress::silent()), 9, 32);
  }
  expect_footprints_match_brute_force(generate_normal_map("bumps", {256, 256}, 1, Progress::silent()), 9, 32);
}

TEST(BinCountTable, NormalExactlyOnAThetaEdgeIsCountedInTheBinAbove) {
  // Texel 0's theta is made an edge; texels 1 and 2 lie below and above it.
  const float t = 0.5f;
  NormalMap map{
      3, 1, {Vec3f(std::sin(t), 0, std::cos(t)), Vec3f(0.1f, 0, 1).normalized(), Vec3f(1, 0, 0.2f).normalized()}};
  const Vec3f& n = map.texels[0];
  const double edge = histogram_theta(n.x(), n.y(), n.z());
  const HistogramBins bins{{0.0, edge, kHalfPi}, 4};
  const std::vector<uint32_t> texel_bin = texel_bins(map, bins);
  EXPECT_EQ(texel_bin, (std::vector<uint32_t>{4, 0, 4}));
  const auto table = bin_count_table(texel_bin, 3, 1, bins.count(), Progress::silent());
  std::vector<uint64_t> counts(8);
  footprint_histogram({3, 1, 8, table}, 0, 0, 1, 1, counts);
  EXPECT_EQ(counts, (std::vector<uint64_t>{0, 0, 0, 0, 1, 0, 0, 0}));
}

TEST(BinCountTable, TablesAboveTheLimitAreRefusedBeforeAnyWork) {
  try {
    check_histogram_table_size(2048, 2048, {9, 32}, "big.png");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(std::string(e.what()).find("would take 4836557952 bytes, above the limit of 4294967296"),
              std::string::npos)
        << e.what();
  }
  // The largest square at 9 x 32 bins: (s + 1)^2 * 288 * 4 <= 2^32.
  const uint32_t s = uint32_t(std::floor(std::sqrt(double(kHistogramMaxTableBytes) / (288 * 4)))) - 1;
  EXPECT_NO_THROW(check_histogram_table_size(s, s, {9, 32}, "fits.png"));
  EXPECT_THROW(check_histogram_table_size(s + 1, s + 1, {9, 32}, "too big.png"), Error);
}

TEST(BinCountTable, TexelsBelowTheHorizonAreRefusedOrRepairedByTheDecoder) {
  Image image{2, 1, 3, {0.0f, 0.0f, 1.0f, 0.6f, 0.0f, -0.8f}};
  ImageFileInfo info;
  info.pixel_format = "float";
  info.is_float = true;
  EXPECT_THROW(decode_normal_map(image, info, {YConvention::plus_y, InvalidTexelPolicy::error}, "t"), Error);
  const LoadedNormalMap repaired =
      decode_normal_map(image, info, {YConvention::plus_y, InvalidTexelPolicy::repair}, "t");
  EXPECT_EQ(repaired.record.repaired_texels, 1u);
  const BakedHistogram baked = bake_histogram(repaired.map, {9, 4}, 1, Progress::silent(), "t");
  ASSERT_EQ(baked.bins.theta_bins(), 2u);  // theta 0 and the horizon
  std::vector<uint64_t> counts(8);
  footprint_histogram(baked.table(), 1, 0, 1, 1, counts);
  EXPECT_EQ(counts[1 * 4 + 0], 1u);  // the repaired texel (1, 0, 0): the last theta bin, phi 0
  // A map handed over with z < 0 (not through the decoder) is refused, naming the texel.
  NormalMap bad{2, 1, {Vec3f(0, 0, 1), Vec3f(0.6f, 0, -0.8f)}};
  try {
    bake_histogram(bad, {9, 32}, 1, Progress::silent(), "bad");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("texel (1, 0)"), std::string::npos) << e.what();
  }
}

using test::loaded;

std::vector<uint8_t> asset_bytes(const LoadedNormalMap& in, const HistogramBakeOptions& options) {
  const uint64_t seed = histogram_seed(in.record.content_hash);
  return histogram_asset_writer(in, options, seed, bake_histogram(in.map, options, seed, Progress::silent(), "t"))
      .serialize();
}

TEST(HistogramAsset, WrittenAssetIsValidAndReadsBackTheSameCounts) {
  const LoadedNormalMap in = loaded(generate_normal_map("scratches", {40, 24}, 2, Progress::silent()));
  EXPECT_EQ(histogram_seed(in.record.content_hash), 0x0123456789abcdefull);
  const std::vector<uint8_t> bytes = asset_bytes(in, {9, 32});
  EXPECT_TRUE(validate_asset(bytes).empty());
  const Asset asset = Asset::parse(bytes, "mem");  // runs the kind's invariants too
  const HistogramAssetView view = histogram_asset_view(asset);
  const BakedHistogram baked = bake_histogram(in.map, {9, 32}, 0x0123456789abcdefull, Progress::silent(), "t");
  EXPECT_EQ(view.bins.theta_edges, baked.bins.theta_edges);
  EXPECT_EQ(view.theta_centres, baked.theta.centres);
  std::vector<uint64_t> a(view.bins.count()), b(view.bins.count());
  for (int64_t k = 0; k < 50; ++k) {
    footprint_histogram(view.table, k * 7, k * 3, 1 + k % 40, 1 + k % 24, a);
    footprint_histogram(baked.table(), k * 7, k * 3, 1 + k % 40, 1 + k % 24, b);
    ASSERT_EQ(a, b);
  }
}

TEST(HistogramAsset, SameBytesWhateverTheThreadCount) {
  const LoadedNormalMap in = loaded(generate_normal_map("bumps", {128, 96}, 5, Progress::silent()));
  set_thread_count(1);
  const std::vector<uint8_t> one = asset_bytes(in, {9, 32});
  set_thread_count(2);
  const std::vector<uint8_t> two = asset_bytes(in, {9, 32});
  set_thread_count(0);
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace mbk
