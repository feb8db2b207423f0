// Infinite zoom through a 2x self-loop ([Han08] thesis Fig. 5.3; issue 18), with the statistics of
// tests/synth/texture_statistics.h, on the self-loop graphs of `gen bumps`, `gen leather` and the real leather_grain
// map (box-reduced to 64 x 64). One analysis per exemplar, then:
//   - at the exemplar's own scale (level L = 6), two 64 x 64 windows near and far (2^40 pixels) from the origin keep
//     >= 90% of the exemplar's variance and each octave band of their mean spectrum within 0.1 (of the total) of the
//     exemplar's;
//   - at depth, 96 x 96 windows at level 8 and 14 (one origin each) and 20 (near and far): plateau blocks at most
//     the exemplar's fraction + 5%, median block variance 0.8x to 1.5x the exemplar's, neighbouring block
//     columns/rows within 2x of each other (no straight regime boundary), no pixel line with more than 2x the median
//     step (no seam), and the window's mean normal within 0.1 of the exemplar's (the loop offsets do not drift:
//     before they faded, level-20 windows of `gen bumps` were tilted by 0.35 to 0.6 and kept 0.46x the variance).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "formats/asset.h"
#include "libbake/gen/generator.h"
#include "libbake/synth/graph_asset.h"
#include "libbake/synth/multiscale_synthesis.h"
#include "tests/real_normal_maps.h"
#include "tests/synth/texture_statistics.h"

namespace mbk {
namespace {

Image image_of(const NormalMap& map) {
  Image im{map.width, map.height, 3, {}};
  for (const Vec3f& n : map.texels) im.pixels.insert(im.pixels.end(), {n.x(), n.y(), n.z()});
  return im;
}

// A 64 x 64 exemplar from a larger power-of-two map: the mean normal of each square of texels, renormalised (the
// map tiles, so the result does too).
Image box_reduced(const NormalMap& map, uint32_t side) {
  const uint32_t f = map.width / side;
  Image im{side, side, 3, std::vector<float>(size_t(side) * side * 3, 0.0f)};
  for (uint32_t y = 0; y < side; ++y)
    for (uint32_t x = 0; x < side; ++x) {
      double s[3] = {0, 0, 0};
      for (uint32_t v = 0; v < f; ++v)
        for (uint32_t u = 0; u < f; ++u) {
          const Vec3f& n = map.at(x * f + u, y * f + v);
          s[0] += n.x(), s[1] += n.y(), s[2] += n.z();
        }
      const double len = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
      for (int c = 0; c < 3; ++c) im.at(x, y, c) = float(s[c] / len);
    }
  return im;
}

GraphTables self_loop_tables(const Image& exemplar) {
  ExemplarGraph g;
  g.exemplars = {{"e", "e.png", "e.png"}};
  g.edges = {{0, 0, 1}};
  g.normal_map = true;
  GraphAnalysisOptions options;
  const GraphAnalysis a = analyse_graph(g, {exemplar}, options, Progress::silent());
  return read_graph_tables(Asset::parse(
      graph_asset_writer(g, a, options, nlohmann::json::object(), nlohmann::json::array()).serialize(), "test"));
}

Image zoom_window(const GraphTables& t, uint32_t level, int64_t x, int64_t y, uint32_t side) {
  SynthesisOptions o;
  o.level = level;
  o.x = x;
  o.y = y;
  o.width = o.height = side;
  return synthesize_window(t, o, Progress::silent());
}

struct DepthLimits {
  double plateau_excess;           // plateau fraction above the exemplar's
  double median_low, median_high;  // median block variance over the exemplar's
  double contrast;                 // block_line_contrast
  double step;                     // step_line_outlier
  double mean_normal;              // distance of the window's mean normal from the exemplar's
};
constexpr DepthLimits kIssueLimits{0.05, 0.8, 1.5, 2, 2, 0.1};

std::array<double, 3> mean_normal(const Image& im) {
  std::array<double, 3> m{0, 0, 0};
  for (size_t i = 0; i < im.pixels.size(); i += 3)
    for (int c = 0; c < 3; ++c) m[c] += im.pixels[i + c];
  for (double& v : m) v /= double(im.pixels.size() / 3);
  return m;
}

// At the exemplar's own scale (level L = 6 of a 64 x 64 exemplar): the variance of 64 x 64 windows and their mean
// octave spectrum against the exemplar's.
void expect_exemplar_scale(const std::string& name, const GraphTables& t, const Image& exemplar) {
  const std::vector<double> want = test::octave_spectrum(exemplar);
  std::vector<double> got(want.size(), 0.0);
  double variance = 0.0;
  const std::vector<int64_t> origins = {0, int64_t(1) << 40};
  for (int64_t origin : origins) {
    const Image w = zoom_window(t, 6, origin, origin / 2 + 17, 64);
    variance += test::window_variance(w) / double(origins.size());
    const std::vector<double> s = test::octave_spectrum(w);
    for (size_t j = 0; j < s.size(); ++j) got[j] += s[j] / double(origins.size());
  }
  std::printf("%s at its own scale: variance %.5f of the exemplar's %.5f; octave spectrum (finest first)", name.c_str(),
              variance, test::window_variance(exemplar));
  for (size_t j = 0; j < want.size(); ++j) std::printf(" %.3f/%.3f", got[j], want[j]);
  std::printf("\n");
  EXPECT_GE(variance, 0.9 * test::window_variance(exemplar)) << name;
  for (size_t j = 0; j < want.size(); ++j) EXPECT_NEAR(got[j], want[j], 0.1) << name << " band " << j;
}

// Windows of 96 x 96 at depth against the limits; prints the table.
void expect_texture_at_every_depth(const std::string& name, const GraphTables& t, const Image& exemplar,
                                   const DepthLimits& limits) {
  const std::vector<double> own = test::block_variances(exemplar);
  const double reference = test::median_of(own), own_plateau = test::plateau_fraction(own, reference);
  const std::array<double, 3> own_mean = mean_normal(exemplar);
  std::printf(
      "%s: exemplar median block variance %.5f, plateau %.2f, contrast %.2f, step %.2f, mean normal %.3f %.3f "
      "%.3f\n",
      name.c_str(), reference, own_plateau, test::block_line_contrast(exemplar), test::step_line_outlier(exemplar),
      own_mean[0], own_mean[1], own_mean[2]);
  const int64_t far = int64_t(1) << 40;
  for (const auto& [level, origin] : std::vector<std::pair<uint32_t, int64_t>>{{8, 0}, {14, far}, {20, 0}, {20, far}}) {
    const Image w = zoom_window(t, level, origin + 3 * level, -origin / 3, 96);
    const std::vector<double> b = test::block_variances(w);
    const double plateau = test::plateau_fraction(b, reference), median = test::median_of(b) / reference;
    const double contrast = test::block_line_contrast(w), step = test::step_line_outlier(w);
    const std::array<double, 3> mean = mean_normal(w);
    const double tilt = std::hypot(mean[0] - own_mean[0], mean[1] - own_mean[1], mean[2] - own_mean[2]);
    std::printf(
        "  level %2u origin %lld: plateau %.2f, median block variance %.2f x, contrast %.2f, step %.2f, mean "
        "normal %.3f %.3f %.3f (%.3f off)\n",
        level, (long long)origin, plateau, median, contrast, step, mean[0], mean[1], mean[2], tilt);
    const std::string where = name + " level " + std::to_string(level) + " origin " + std::to_string(origin);
    EXPECT_LE(plateau, own_plateau + limits.plateau_excess) << where;
    EXPECT_GE(median, limits.median_low) << where;
    EXPECT_LE(median, limits.median_high) << where;
    EXPECT_LE(contrast, limits.contrast) << where;
    EXPECT_LE(step, limits.step) << where;
    EXPECT_LE(tilt, limits.mean_normal) << where;
  }
}

void expect_zoom_stays_the_texture(const std::string& name, const Image& exemplar) {
  const GraphTables t = self_loop_tables(exemplar);
  expect_exemplar_scale(name, t, exemplar);
  expect_texture_at_every_depth(name, t, exemplar, kIssueLimits);
}

TEST(SelfLoopZoom, GenBumpsStaysTheTextureAtEveryDepth) {
  expect_zoom_stays_the_texture("bumps", image_of(generate_bumps({64, 64}, 1, Progress::silent())));
}

TEST(SelfLoopZoom, GenLeatherStaysTheTextureAtEveryDepth) {
  expect_zoom_stays_the_texture("leather", image_of(generate_leather({64, 64}, 2, Progress::silent())));
}

TEST(SelfLoopZoom, RealLeatherGrainStaysTheTextureAtEveryDepth) {
  int maps = 0;
  test::for_each_real_normal_map([&](const NormalMap& map, const std::string& file) {
    if (file != "leather_grain.png") return;
    ++maps;
    expect_zoom_stays_the_texture(file, box_reduced(map, 64));
  });
  if (maps == 0) GTEST_SKIP() << "no leather_grain.png among the real normal maps";
}

}  // namespace
}  // namespace mbk
