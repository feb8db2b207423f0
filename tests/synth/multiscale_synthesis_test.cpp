// Multiscale synthesis ([Han08] thesis Sec. 5.2.2; libbake/synth/multiscale_synthesis.h): windows are independent
// (tiles equal the whole, bit for bit, at several levels and thread counts); a single exemplar with a self-loop
// synthesized 10 levels past its own resolution keeps matching its neighbourhoods and its variety; an inconsistent
// graph's colours stay those of the coarse exemplar with correction and drift without it.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include "formats/asset.h"
#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/synth/graph_asset.h"
#include "libbake/synth/multiscale_synthesis.h"

namespace mbk {
namespace {

// A tileable blob texture: a sum of a few random periodic cosines, values in about [0, 1].
Image blobs(uint32_t m, uint32_t seed, float offset = 0.0f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> phase(0, 2 * std::numbers::pi);
  std::uniform_int_distribution<int> freq(1, 4);
  std::vector<std::array<double, 4>> waves;
  for (int w = 0; w < 6; ++w) waves.push_back({double(freq(rng)), double(freq(rng)), phase(rng), phase(rng)});
  Image im{m, m, 3, {}};
  for (uint32_t y = 0; y < m; ++y)
    for (uint32_t x = 0; x < m; ++x) {
      double v = 0.0;
      for (const auto& w : waves) v += std::cos(2 * std::numbers::pi * (w[0] * x + w[1] * y) / m + w[2]);
      const double g = 0.5 + 0.12 * v;
      im.pixels.insert(im.pixels.end(), {float(g + offset), float(0.8 * g + offset), float(0.3 + 0.4 * g + offset)});
    }
  return im;
}

GraphTables tables_of(const ExemplarGraph& g, const std::vector<Image>& images) {
  GraphAnalysisOptions options;
  const GraphAnalysis a = analyse_graph(g, images, options, Progress::silent());
  return read_graph_tables(Asset::parse(
      graph_asset_writer(g, a, options, nlohmann::json::object(), nlohmann::json::array()).serialize(), "test"));
}

ExemplarGraph self_loop_graph() {
  ExemplarGraph g;
  g.exemplars = {{"a", "a.png", "a.png"}};
  g.edges = {{0, 0, 1}};
  return g;
}

Image window(const GraphTables& t, uint32_t level, int64_t x, int64_t y, uint32_t w, uint32_t h,
             SynthesisStatistics* stats = nullptr, bool correct = true) {
  SynthesisOptions o;
  o.level = level;
  o.x = x;
  o.y = y;
  o.width = w;
  o.height = h;
  o.correct_inconsistency = correct;
  return synthesize_window(t, o, Progress::silent(), stats);
}

TEST(MultiscaleSynthesis, TilesEqualTheWholeWindowBitForBit_LevelsAndThreads) {
  const GraphTables t = tables_of(self_loop_graph(), {blobs(16, 1)});
  const int threads = thread_count();
  for (const uint32_t level : {3u, 5u, 7u})
    for (const int n : {1, 2}) {
      set_thread_count(n);
      const Image whole = window(t, level, -13, 7, 24, 20);
      for (const auto& [x, y, w, h] :
           {std::array<int64_t, 4>{-13, 7, 11, 9}, {-2, 7, 13, 9}, {-13, 16, 24, 11}, {0, 20, 1, 1}}) {
        const Image tile = window(t, level, x, y, uint32_t(w), uint32_t(h));
        for (int64_t ty = 0; ty < h; ++ty)
          for (int64_t tx = 0; tx < w; ++tx)
            for (uint32_t c = 0; c < 3; ++c)
              ASSERT_EQ(tile.at(uint32_t(tx), uint32_t(ty), c),
                        whole.at(uint32_t(x - (-13) + tx), uint32_t(y - 7 + ty), c))
                  << "level " << level << ", threads " << n << ", tile " << x << "," << y;
      }
    }
  set_thread_count(threads);
}

// The same with transfers at work (an inconsistent two-exemplar graph), far from the origin (where a float
// computation of the transfer interpolation or a 32-bit hash would break), and with 1 and 3 passes (other paddings).
TEST(MultiscaleSynthesis, TilesEqualTheWholeFarAwayWithTransfersAndOtherPassCounts) {
  ExemplarGraph g;
  g.exemplars = {{"a", "a.png", "a.png"}, {"b", "b.png", "b.png"}};
  g.edges = {{0, 1, 1}, {1, 1, 1}};
  const GraphTables t = tables_of(g, {blobs(16, 5), blobs(16, 6, 0.3f)});
  for (const int64_t origin : {int64_t(-1) << 40, (int64_t(1) << 62) - 64})
    for (const uint32_t passes : {1u, 3u}) {
      SynthesisOptions o;
      o.level = 7;
      o.passes = passes;
      o.x = origin;
      o.y = -origin / 2;
      o.width = 20;
      o.height = 12;
      const Image whole = synthesize_window(t, o, Progress::silent());
      SynthesisOptions tile = o;
      tile.x = o.x + 7;
      tile.y = o.y + 5;
      tile.width = 9;
      tile.height = 6;
      const Image part = synthesize_window(t, tile, Progress::silent());
      for (uint32_t y = 0; y < tile.height; ++y)
        for (uint32_t x = 0; x < tile.width; ++x)
          for (uint32_t c = 0; c < 3; ++c)
            ASSERT_EQ(part.at(x, y, c), whole.at(x + 7, y + 5, c)) << "origin " << origin << ", passes " << passes;
    }
  // No 2^32 period: a window 2^42 pixels away is another part of the texture.
  SynthesisOptions near_origin, far;
  near_origin.level = far.level = 7;
  near_origin.width = far.width = near_origin.height = far.height = 8;
  far.x = int64_t(1) << 42;
  EXPECT_NE(synthesize_window(t, near_origin, Progress::silent()).pixels,
            synthesize_window(t, far, Progress::silent()).pixels);
}

TEST(MultiscaleSynthesis, WindowsOutsideTheLimitsAreCommandLineErrors) {
  const GraphTables t = tables_of(self_loop_graph(), {blobs(16, 1)});
  SynthesisOptions o;
  o.x = (int64_t(1) << 62) - 3;
  o.width = 4;
  EXPECT_THROW(synthesize_window(t, o, Progress::silent()), Error);
  o.x = 0;
  o.width = 8192;
  o.height = 4096;
  EXPECT_THROW(synthesize_window(t, o, Progress::silent()), Error);
}

double variance_of(const Image& im, uint32_t c) {
  double mean = 0.0, sq = 0.0;
  const size_t n = size_t(im.width) * im.height;
  for (size_t i = 0; i < n; ++i) mean += im.pixels[i * im.channels + c];
  mean /= double(n);
  for (size_t i = 0; i < n; ++i) sq += std::pow(im.pixels[i * im.channels + c] - mean, 2);
  return sq / double(n);
}

// A texture that a 2x self-loop describes truly: periodic noise with equal amplitude in every octave, so that its 2x
// magnification has the statistics of the texture itself (minus the finest octave). Values in about [0, 1].
Image octaves(uint32_t m, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> phase(0, 2 * std::numbers::pi);
  Image im{m, m, 3, std::vector<float>(size_t(m) * m * 3, 0.5f)};
  for (uint32_t f = 1; f < m / 2; f *= 2)
    for (int w = 0; w < 3; ++w) {
      const double fx = f * (w == 1 ? 0 : 1), fy = f * (w == 0 ? 0 : 1), p = phase(rng);
      for (uint32_t y = 0; y < m; ++y)
        for (uint32_t x = 0; x < m; ++x)
          for (uint32_t c = 0; c < 3; ++c)
            im.pixels[(size_t(y) * m + x) * 3 + c] +=
                float(0.05 * std::cos(2 * std::numbers::pi * (fx * x + fy * y) / m + p + c));
    }
  return im;
}

// A 32 x 32 self-similar exemplar (L = 5) with a 2x self-loop, synthesized to level 15: ten levels below its own
// texels. The mean matching error per level stays bounded (no drift into incoherent output), and the finest
// window keeps the variety of the exemplar's own scale (it does not fade to a flat colour).
// Past the finest level of an exemplar with nowhere to go (the root alone) a window only magnifies: every pixel of
// level L + 2 is the level L + 1 pixel at half its coordinates (a 16 x 16 exemplar, L = 4; near and far from the
// origin). Correction at the output level once shuffled the magnified texels into a grid of squares.
TEST(MultiscaleSynthesis, PastTheFinestLevelOfAnExemplarWithNowhereToGoWindowsOnlyMagnify) {
  ExemplarGraph g;
  g.exemplars = {{"a", "a.png", "a.png"}};
  const GraphTables t = tables_of(g, {blobs(16, 3)});
  for (const int64_t origin : {int64_t(-6), (int64_t(1) << 40) + 6}) {
    const Image coarse = window(t, 5, origin, -origin, 24, 24), fine = window(t, 6, 2 * origin, -2 * origin, 48, 48);
    for (uint32_t y = 0; y < 48; ++y)
      for (uint32_t x = 0; x < 48; ++x)
        for (uint32_t c = 0; c < 3; ++c)
          ASSERT_EQ(fine.at(x, y, c), coarse.at(x / 2, y / 2, c)) << "origin " << origin << ", " << x << "," << y;
  }
}

TEST(MultiscaleSynthesis, SelfLoopZoomTenLevelsDeepStaysCoherent) {
  const Image exemplar = octaves(32, 2);
  const GraphTables t = tables_of(self_loop_graph(), {exemplar});
  SynthesisStatistics stats;
  const Image at_scale = window(t, 5, 0, 0, 64, 64), deep = window(t, 15, 1000, -777, 64, 64, &stats);
  ASSERT_EQ(stats.matching_error.size(), 16u);
  const double at_exemplar = stats.matching_error[5];
  for (size_t l = 5; l < stats.matching_error.size(); ++l) {
    std::cout << "level " << l << ": mean matching error " << stats.matching_error[l] << "\n";
    EXPECT_LT(stats.matching_error[l], 3.0 * at_exemplar + 1e-4) << l;
  }
  std::cout << "variance: exemplar " << variance_of(exemplar, 0) << ", level 5 " << variance_of(at_scale, 0)
            << ", level 15 " << variance_of(deep, 0) << "\n";
  EXPECT_GT(variance_of(deep, 0), 0.3 * variance_of(at_scale, 0));
}

// A -> B (r = 1) with B = A's blobs re-drawn 0.3 brighter: B's neighbourhoods match A's only up to that offset.
// With correction the transfers keep the output at A's brightness (the coarse level is the prior, Sec. 5.3);
// without, pixels that move into B take B's brightness.
TEST(MultiscaleSynthesis, InconsistencyCorrectionKeepsTheCoarseExemplarsColours) {
  ExemplarGraph g;
  g.exemplars = {{"a", "a.png", "a.png"}, {"b", "b.png", "b.png"}};
  g.edges = {{0, 1, 1}, {1, 1, 1}};
  const Image a = blobs(16, 3), b = blobs(16, 4, 0.3f);
  const GraphTables t = tables_of(g, {a, b});
  double mean_a = 0.0;
  for (size_t i = 0; i < a.pixels.size(); i += 3) mean_a += a.pixels[i] / (a.pixels.size() / 3.0);
  const auto mean_red = [](const Image& im) {
    double m = 0.0;
    for (size_t i = 0; i < im.pixels.size(); i += 3) m += im.pixels[i] / (im.pixels.size() / 3.0);
    return m;
  };
  const double with = mean_red(window(t, 8, 0, 0, 64, 64)),
               without = mean_red(window(t, 8, 0, 0, 64, 64, nullptr, false));
  std::cout << "mean red: exemplar A " << mean_a << ", corrected " << with << ", uncorrected " << without << "\n";
  EXPECT_LT(std::abs(with - mean_a), 0.1);
  EXPECT_GT(without - mean_a, 0.2);
}

}  // namespace
}  // namespace mbk
