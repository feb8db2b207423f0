// The range query of the blended microstructure (libbake/glint/blended_range.h; [Wang20] Sec. 4.3-4.5): over
// >= 10,000 random nodes per blend mode (random target patches, negative indices included, log-uniform node
// sides from one texel to the whole target patch), at 16 and 8 bits, on generated maps, the node bounds contain
// the brute-force blended extremes: for every texel of the node, the blend of its four example texels' exact
// leaf intervals (blended by an independent scalar implementation of Eqs. 4-6 below, at the weights of the
// texel's own centre) and the point query's normal there. Also: the variance-preserving divisor is bounded
// inside the patch (the corners-only bound provably fails there), element bounds equal the scalar blend,
// constant maps give point bounds, and odd patch sides or mismatched tables are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "formats/error.h"
#include "formats/lut_layout.h"
#include "libbake/core/progress.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/glint_surface.h"
#include "libbake/glint/blended_range.h"
#include "libbake/glint/element_normal_bounds.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/rmq_table.h"

namespace mbk {
namespace {

constexpr std::array<GlintBlendMode, 4> kModes = {GlintBlendMode::none, GlintBlendMode::linear,
                                                  GlintBlendMode::variance, GlintBlendMode::histogram};

// The blend of one channel written out directly from [Wang20] Eqs. 4-6 (independent of blended_range.cpp).
double blend_scalar(GlintBlendMode mode, const TargetPatchLocation& loc, const std::array<double, 4>& v, double mean,
                    const StandardizationChannelTables& lut) {
  if (mode == GlintBlendMode::none) return v[(loc.local.x() >= 0.5 ? 1 : 0) + (loc.local.y() >= 0.5 ? 2 : 0)];
  double sum = 0.0, w2 = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double x = mode == GlintBlendMode::histogram ? lut.standardize(v[k]).value : v[k];
    sum += loc.corners[k].weight * x;
    w2 += loc.corners[k].weight * loc.corners[k].weight;
  }
  if (mode == GlintBlendMode::linear) return sum;
  if (mode == GlintBlendMode::variance) return (sum - mean) / std::sqrt(w2) + mean;
  return lut.destandardize(sum / std::sqrt(w2)).value;
}

struct Truth {
  RmqBounds box;  // blended leaf intervals
  Vec2 n;         // the point query at the texel's centre
};

// Brute force for target texel t: locate its centre, read the four example texels the corners land on, blend
// the ends of their leaf intervals (the blend is monotone, so these are its extremes over the intervals).
Truth brute_force_element(const GlintPointQuery& q, const RmqTableView& table, int64_t t0, int64_t t1) {
  const Vec2 u(double(t0) + 0.5, double(t1) + 0.5);
  const TargetPatchLocation loc = q.grid().locate(u);
  std::array<RmqBounds, 4> leaf;
  for (int k = 0; k < 4; ++k) {
    const Vec2 e = loc.corners[k].example_point;  // a texel centre: floor gives the texel
    const uint32_t x = uint32_t(std::floor(e.x())), row = uint32_t(std::floor(e.y()));
    leaf[k] = table.query(x, row, 1, 1);  // the stored leaf: it holds the exact one
    const RmqBounds exact = element_normal_bounds(q.example(), x, row);
    EXPECT_TRUE(leaf[k].min_x <= exact.min_x && leaf[k].max_x >= exact.max_x && leaf[k].min_y <= exact.min_y &&
                leaf[k].max_y >= exact.max_y);
  }
  Truth t;
  std::array<double, 4> v;
  double* out[4] = {&t.box.min_x, &t.box.max_x, &t.box.min_y, &t.box.max_y};
  for (int end = 0; end < 4; ++end) {
    for (int k = 0; k < 4; ++k) {
      const RmqBounds& b = leaf[k];
      v[k] = end == 0 ? b.min_x : end == 1 ? b.max_x : end == 2 ? b.min_y : b.max_y;
    }
    const int ch = end / 2;
    *out[end] = blend_scalar(q.mode(), loc, v, q.example_mean()[ch], q.lut()->channels[ch]);
  }
  t.n = q.evaluate(u).n;
  return t;
}

struct Fixture {
  explicit Fixture(const char* kind)
      : example(generate_normal_map(kind, {128, 96}, 7, Progress::silent())),
        lut(bake_standardization_lut(example, kLutDefaultSize, Progress::silent())),
        rmq16(build_rmq_table(example, 32, 16, Progress::silent())),
        rmq8(build_rmq_table(example, 32, 8, Progress::silent())) {}
  NormalMap example;
  BakedLut lut;
  RmqTable rmq16, rmq8;
};

uint32_t log_uniform_side(std::mt19937_64& rng, uint32_t max) {
  const double side = std::floor(std::exp(std::uniform_real_distribution<double>(0.0, std::log(max + 1.0))(rng)));
  return std::clamp(uint32_t(side), 1u, max);
}

void check_nodes_contain_brute_force(const char* kind) {
  const Fixture f(kind);
  for (const RmqTable* table : {&f.rmq16, &f.rmq8}) {
    const RmqTableView view = table->view();
    for (const GlintBlendMode mode : kModes) {
      const GlintPointQuery q(f.example, 32, 5, mode, &f.lut.tables);
      const GlintRangeQuery r(q, view);
      const uint32_t h = r.target_side();
      std::mt19937_64 rng(99);
      std::uniform_int_distribution<int64_t> patch(-3000, 3000);
      double slack = 0.0;
      int64_t texels = 0;
      constexpr int kNodes = 10000;
      for (int n = 0; n < kNodes; ++n) {
        TargetNode node;
        node.patch_i = patch(rng);
        node.patch_j = patch(rng);
        node.width = log_uniform_side(rng, h);
        node.height = log_uniform_side(rng, h);
        node.x0 = std::uniform_int_distribution<uint32_t>(0, h - node.width)(rng);
        node.y0 = std::uniform_int_distribution<uint32_t>(0, h - node.height)(rng);
        const RmqBounds b = r.node_bounds(node);
        RmqBounds hull{INFINITY, -INFINITY, INFINITY, -INFINITY};
        for (uint32_t y = node.y0; y < node.y0 + node.height; ++y)
          for (uint32_t x = node.x0; x < node.x0 + node.width; ++x) {
            const Truth t = brute_force_element(q, view, node.patch_i * h + x, node.patch_j * h + y);
            hull = {std::min(hull.min_x, t.box.min_x), std::max(hull.max_x, t.box.max_x),
                    std::min(hull.min_y, t.box.min_y), std::max(hull.max_y, t.box.max_y)};
            ASSERT_LE(t.box.min_x, t.n.x() + 1e-12) << glint_blend_mode_name(mode);
            ASSERT_GE(t.box.max_x, t.n.x() - 1e-12) << glint_blend_mode_name(mode);
            ASSERT_LE(t.box.min_y, t.n.y() + 1e-12) << glint_blend_mode_name(mode);
            ASSERT_GE(t.box.max_y, t.n.y() - 1e-12) << glint_blend_mode_name(mode);
            ++texels;
          }
        ASSERT_LE(b.min_x, hull.min_x) << kind << " " << glint_blend_mode_name(mode) << " node " << n;
        ASSERT_GE(b.max_x, hull.max_x) << kind << " " << glint_blend_mode_name(mode) << " node " << n;
        ASSERT_LE(b.min_y, hull.min_y) << kind << " " << glint_blend_mode_name(mode) << " node " << n;
        ASSERT_GE(b.max_y, hull.max_y) << kind << " " << glint_blend_mode_name(mode) << " node " << n;
        slack += (b.max_x - b.min_x) / std::max(hull.max_x - hull.min_x, 1e-9);
      }
      std::printf("[ info ] %s, %u bits, %s: %d nodes, %lld texels, mean width ratio (bound / truth) n_x %.3f\n", kind,
                  view.layout().bits, glint_blend_mode_name(mode), kNodes, (long long)texels, slack / kNodes);
    }
  }
}

TEST(GlintRangeQuery, NodeBoundsContainBruteForceBlendedExtremes_Bumps_AllModes) {
  check_nodes_contain_brute_force("bumps");
}
TEST(GlintRangeQuery, NodeBoundsContainBruteForceBlendedExtremes_Flakes_AllModes) {
  check_nodes_contain_brute_force("flakes");
}

// Variance blending divides by W = ||w||, which is SMALLEST at the patch centre (1/2) and 1 at its corners: a
// node spanning the centre must use W's interior minimum. Constant corner ranges 0.9 with mean 0: the blend at
// the centre is 0.9 / 0.5 = 1.8, while W at the node's corners f = 0.1 or 0.9 is 0.82 (0.9 / 0.82 = 1.10).
TEST(GlintRangeQuery, VarianceBoundUsesInteriorMinimumOfWeightNorm) {
  const RmqBounds c{0.9, 0.9, -0.9, -0.9};
  const std::array<RmqBounds, 4> corners = {c, c, c, c};
  const RmqBounds b =
      blend_range_bounds(GlintBlendMode::variance, Vec2(0.1, 0.1), Vec2(0.9, 0.9), corners, Vec2::Zero(), nullptr);
  EXPECT_GE(b.max_x, 1.8);
  EXPECT_LE(b.min_y, -1.8);
  // The corners-only bound would be 0.9 / W(0.1, 0.1), below the centre's value: the trap is real.
  const double w_corner = (0.9 * 0.9 + 0.1 * 0.1);
  EXPECT_LT(0.9 / w_corner, 1.8 - 0.5);
  // A node that stays on one side of the centre gets W's minimum at its edge nearest 1/2.
  const RmqBounds side =
      blend_range_bounds(GlintBlendMode::variance, Vec2(0.0, 0.0), Vec2(0.25, 0.25), corners, Vec2::Zero(), nullptr);
  const double q = 0.75 * 0.75 + 0.25 * 0.25;  // q(0.25)
  EXPECT_NEAR(side.max_x, 0.9 / q, 1e-9);
}

// A one-point box gives the scalar blend of the stored leaves (the element bounds of blended_range.h), for every
// mode.
TEST(GlintRangeQuery, ElementBoundsEqualScalarBlendOfLeafIntervals_AllModes) {
  const Fixture f("leather");
  const RmqTableView view = f.rmq16.view();
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int64_t> t(-100000, 100000);
  for (const GlintBlendMode mode : kModes) {
    const GlintPointQuery q(f.example, 32, 11, mode, &f.lut.tables);
    const GlintRangeQuery r(q, view);
    for (int n = 0; n < 2000; ++n) {
      const int64_t t0 = t(rng), t1 = t(rng);
      const RmqBounds b = r.element_bounds(t0, t1);
      const Truth truth = brute_force_element(q, view, t0, t1);
      ASSERT_NEAR(b.min_x, truth.box.min_x, 1e-11) << glint_blend_mode_name(mode);
      ASSERT_NEAR(b.max_x, truth.box.max_x, 1e-11) << glint_blend_mode_name(mode);
      ASSERT_NEAR(b.min_y, truth.box.min_y, 1e-11) << glint_blend_mode_name(mode);
      ASSERT_NEAR(b.max_y, truth.box.max_y, 1e-11) << glint_blend_mode_name(mode);
    }
  }
}

TEST(GlintRangeQuery, ConstantExampleGivesPointBounds_AllModes) {
  NormalMap flat{64, 64, std::vector<Vec3f>(64 * 64, Vec3f(0.3f, -0.2f, std::sqrt(1.0f - 0.13f)))};
  const BakedLut lut = bake_standardization_lut(flat, 128, Progress::silent());
  const RmqTable table = build_rmq_table(flat, 16, 16, Progress::silent());
  const RmqTableView view = table.view();
  for (const GlintBlendMode mode : kModes) {
    const GlintPointQuery q(flat, 16, 1, mode, &lut.tables);
    const GlintRangeQuery r(q, view);
    const RmqBounds b = r.node_bounds({-7, 3, 0, 0, 8, 8});
    EXPECT_NEAR(b.min_x, 0.3, 1e-6) << glint_blend_mode_name(mode);
    EXPECT_NEAR(b.max_x, 0.3, 1e-6) << glint_blend_mode_name(mode);
    EXPECT_NEAR(b.min_y, -0.2, 1e-6) << glint_blend_mode_name(mode);
    EXPECT_NEAR(b.max_y, -0.2, 1e-6) << glint_blend_mode_name(mode);
  }
}

TEST(GlintRangeQuery, OddPatchSideOrMismatchedTableIsRefused) {
  const Fixture f("bumps");
  const RmqTableView view = f.rmq16.view();
  const GlintPointQuery odd(f.example, 31, 1, GlintBlendMode::linear);
  EXPECT_THROW(GlintRangeQuery(odd, view), Error);
  const NormalMap other = generate_normal_map("bumps", {64, 64}, 7, Progress::silent());
  const GlintPointQuery q(other, 32, 1, GlintBlendMode::linear);
  EXPECT_THROW(GlintRangeQuery(q, view), Error);
}

}  // namespace
}  // namespace mbk
