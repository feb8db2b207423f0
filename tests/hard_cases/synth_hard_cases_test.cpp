// Hard cases of multiscale synthesis ([Han08]; libbake/synth/, formats/admissible_levels.h): self-loops that skip
// levels (r = 2 and r = 4: each loop magnifies 4x or 16x, so a synthesis level's candidates come from every r-th
// stack level) and windows at the +-2^62 limits of the plane. The exemplar is a 32 x 32 `gen bumps` normal map
// (stack levels 0..5), so every synthesized pixel must be a unit normal.
// (r = 1 ten levels deep: MultiscaleSynthesis.SelfLoopZoomTenLevelsDeepStaysCoherent; tiles 2^62 - 64 away:
// MultiscaleSynthesis.TilesEqualTheWholeFarAwayWithTransfersAndOtherPassCounts.)
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "formats/asset.h"
#include "formats/error.h"
#include "libbake/gen/generator.h"
#include "libbake/synth/graph_asset.h"
#include "libbake/synth/multiscale_synthesis.h"

namespace mbk {
namespace {

constexpr uint32_t kSide = 32, kFinest = 5;  // stack levels 0..5

GraphTables bumps_with_self_loop(uint32_t r) {
  const NormalMap map = generate_normal_map("bumps", {kSide, kSide}, 4, Progress::silent());
  Image exemplar{kSide, kSide, 3, {}};
  for (const Vec3f& n : map.texels) exemplar.pixels.insert(exemplar.pixels.end(), {n.x(), n.y(), n.z()});
  ExemplarGraph g;
  g.exemplars = {{"e", "e.png", "e.png"}};
  g.edges = {{0, 0, r}};
  g.normal_map = true;
  const GraphAnalysisOptions options;
  const GraphAnalysis analysis = analyse_graph(g, {exemplar}, options, Progress::silent());
  const AssetWriter writer =
      graph_asset_writer(g, analysis, options, nlohmann::json::object(), nlohmann::json::array());
  return read_graph_tables(Asset::parse(writer.serialize(), "self loop"));
}

Image window(const GraphTables& t, uint32_t level, int64_t x, int64_t y, uint32_t side,
             SynthesisStatistics* statistics = nullptr) {
  SynthesisOptions o;
  o.level = level, o.x = x, o.y = y, o.width = o.height = side;
  return synthesize_window(t, o, Progress::silent(), statistics);
}

double variance(const Image& im) {
  double sum = 0.0, square = 0.0;
  for (float v : im.pixels) sum += v, square += double(v) * v;
  const double n = double(im.pixels.size());
  return square / n - (sum / n) * (sum / n);
}

void expect_unit_normals(const Image& im) {
  for (size_t i = 0; i < im.pixels.size(); i += 3)
    ASSERT_NEAR(Vec3(im.pixels[i], im.pixels[i + 1], im.pixels[i + 2]).norm(), 1.0, 1e-5) << "pixel " << i / 3;
}

// The superexemplar's stack levels derived here from the thesis's rules (Sec. 5.2.1.2, 5.4) for one exemplar with a
// self-loop r: A(k) = {l < L : k - l in {0, r}}; level 0 is the closure of {0}; level t + 1 the closure of
// {k + 1 : k < L in level t} (the finest level L stays only where it has no admissible level, and here it has L - r).
std::set<uint32_t> closure(std::set<uint32_t> s, uint32_t r) {
  for (bool grew = true; grew;) {
    grew = false;
    for (uint32_t k : std::set<uint32_t>(s))
      for (uint32_t l : {k, k >= r ? k - r : kFinest})
        if (l < kFinest && s.insert(l).second) grew = true;
  }
  return s;
}

// Self-loop r: the admissible stack levels at every synthesis level 0..64 against the derivation above, and a window
// 2r + 3 levels below the exemplar's own scale: unit normals, mean matching error per level at most 3x that at the
// exemplar's scale (no drift into incoherence), and at least 0.3x the variance of the exemplar-scale window (it does
// not fade into a flat colour).
void expect_self_loop_synthesis(uint32_t r) {
  const GraphTables t = bumps_with_self_loop(r);
  const SuperexemplarLevels levels = superexemplar_levels(1, {{0, 0, r}}, kFinest + 1, 0);
  std::set<uint32_t> derived = closure({0}, r);
  for (uint64_t level = 0; level <= 64; ++level) {
    std::vector<StackLevel> expected;
    for (uint32_t k : derived) expected.push_back({0, k});
    ASSERT_EQ(levels.at(level), expected) << "synthesis level " << level;
    std::set<uint32_t> up;
    for (uint32_t k : derived)
      if (k < kFinest) up.insert(k + 1);
    derived = closure(up, r);
  }
  SynthesisStatistics statistics;
  const uint32_t deep = kFinest + 2 * r + 3;
  const Image at_scale = window(t, kFinest, 0, 0, 32), far = window(t, deep, -777, 1234, 32, &statistics);
  expect_unit_normals(far);
  ASSERT_EQ(statistics.matching_error.size(), deep + 1);
  for (uint32_t l = kFinest; l <= deep; ++l)
    EXPECT_LE(statistics.matching_error[l], 3.0 * statistics.matching_error[kFinest] + 1e-4) << "level " << l;
  EXPECT_GE(variance(far), 0.3 * variance(at_scale));
}

// Protects against: a loop that skips a level: synthesis levels alternate between the even and the odd stack levels
// ({0, 2, 4}, {1, 3, 5}), so correction must always find candidates of the right parity, never an empty set.
TEST(HardCases, SynthGraphSelfLoopAtR2) { expect_self_loop_synthesis(2); }

// Protects against: the largest loop a 6-level stack allows (r = 4 < r_max = 5): the loop's destination is 4
// levels coarser and most synthesis levels see one or two stack levels only.
TEST(HardCases, SynthGraphSelfLoopAtR4) { expect_self_loop_synthesis(4); }

// Window at the edge of the plane: a tile of it equals the same pixels of the whole window, bit for bit (no overflow
// in the padded regions of coarser levels, which halve towards -inf and +inf); the texture there has the statistics
// it has near the origin (stationary: matching errors per level within 2x); one pixel further is refused.
void expect_window_at_the_limit(int64_t x, int64_t y) {
  const GraphTables t = bumps_with_self_loop(1);
  SynthesisStatistics at_limit, at_origin;
  const Image whole = window(t, 7, x, y, 24, &at_limit);
  window(t, 7, 0, 0, 24, &at_origin);
  expect_unit_normals(whole);
  SynthesisOptions tile;
  tile.level = 7, tile.x = x + 5, tile.y = y + 11, tile.width = 13, tile.height = 9;
  const Image part = synthesize_window(t, tile, Progress::silent());
  for (uint32_t j = 0; j < tile.height; ++j)
    for (uint32_t i = 0; i < tile.width; ++i)
      for (uint32_t c = 0; c < 3; ++c) ASSERT_EQ(part.at(i, j, c), whole.at(i + 5, j + 11, c)) << i << "," << j;
  for (uint32_t l = 1; l <= 7; ++l) {
    EXPECT_LE(at_limit.matching_error[l], 2.0 * at_origin.matching_error[l] + 1e-4) << l;
    EXPECT_GE(at_limit.matching_error[l], 0.5 * at_origin.matching_error[l] - 1e-4) << l;
  }
  SynthesisOptions beyond;
  beyond.level = 7, beyond.width = beyond.height = 24;
  beyond.x = x < 0 ? x - 1 : x, beyond.y = y > 0 ? y + 1 : y;
  EXPECT_THROW(synthesize_window(t, beyond, Progress::silent()), Error);
}

constexpr int64_t kLimit = int64_t(1) << 62;

// Protects against: int64 overflow at the negative end of the plane (x = -2^62 exactly, the documented limit).
TEST(HardCases, SynthWindowAtMinus2To62) { expect_window_at_the_limit(-kLimit, -kLimit + 100); }

// Protects against: int64 overflow at the positive end (the window's last pixel at 2^62 - 1 in x and y).
TEST(HardCases, SynthWindowAtPlus2To62) { expect_window_at_the_limit(kLimit - 24, kLimit - 24); }

}  // namespace
}  // namespace mbk
