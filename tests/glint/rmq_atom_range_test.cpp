// The RMQ range that stores the flat ground exactly (libbake/glint/rmq_atom_range.h): over random data ranges
// and atoms at 8 and 16 bits (ends, zero, -0, tiny and float-rounded values), the range holds the data, the atom
// is the value of a code through the reader's formula, and the quantum grows by at most (Q / (Q - 1)) (1 + 2^-7);
// without an atom, with one outside the data, or for a constant channel the data's range is kept. On maps with
// flat ground (`gen scratches`, maps 90-99% one value) every plateau texel's stored leaf reads back as exactly
// [x0, x0], and the range query's bounds of a plateau node are that point under the blend modes that keep flat ground
// flat - the property that lets the P-NDF prune and aggregate flat ground (glint_pndf.h) instead of crossing the atom's
// steep G.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "formats/lut_layout.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/blended_range.h"
#include "libbake/glint/element_normal_bounds.h"
#include "libbake/glint/glint_technique.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/rmq_atom_range.h"
#include "libbake/glint/rmq_table.h"
#include "tests/glint/atom_maps.h"

namespace mbk {
namespace {

// The range holds the data, the atom reads back exactly, and the quantum is at most the stated factor coarser.
// Float atoms (what normal maps hold) must be made exact; a double with all 53 bits set may not fit, and then
// the data's range is kept.
void expect_exact_atom(const RmqRange& data, double atom, uint32_t bits) {
  const RmqRange r = rmq_range_with_exact_value(data, atom, bits);
  ASSERT_LE(r.lo, data.lo);
  ASSERT_GE(r.hi, data.hi);
  const RmqQuantizer q(r, bits);
  if (double(float(atom)) != atom && r.lo == data.lo && r.hi == data.hi) return;
  ASSERT_EQ(q.value(q.up(atom)), atom) << "data [" << data.lo << ", " << data.hi << "] atom " << atom;
  const double q_max = rmq_code_max(bits);
  ASSERT_LE(r.quantum(bits),
            data.quantum(bits) * q_max / (q_max - 1) * (1.0 + std::ldexp(1.0, 1 - kRmqAtomQuantumBits)));
}

TEST(RmqAtomRange, AtomIsACodeAndTheRangeHoldsTheData_RandomRanges) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (uint32_t bits : {8u, 16u})
    for (int i = 0; i < 20000; ++i) {
      double a = 4.0 * unit(rng) - 2.0, b = 4.0 * unit(rng) - 2.0;
      if (i % 7 == 0) b = a + std::ldexp(unit(rng), -int(unit(rng) * 40));  // narrow ranges down to ~1e-12
      const RmqRange data{std::min(a, b), std::max(a, b)};
      if (!(data.hi > data.lo)) continue;
      double atom = data.lo + unit(rng) * (data.hi - data.lo);
      if (i % 5 == 0) atom = double(float(atom));  // a float normal component, as the maps hold
      if (i % 11 == 0) atom = data.lo;
      if (i % 13 == 0) atom = data.hi;
      if (atom < data.lo || atom > data.hi) continue;  // float rounding left the data
      expect_exact_atom(data, atom, bits);
    }
}

TEST(RmqAtomRange, HardCases) {
  for (uint32_t bits : {8u, 16u}) {
    expect_exact_atom({-1.76404572, 1.73590088}, -0.0, bits);  // scratches' n_x: flat ground at -0
    expect_exact_atom({-1.0, 1.0}, 0.0, bits);
    expect_exact_atom({0.0, 1.0}, 0.0, bits);  // the atom at an end
    expect_exact_atom({0.0, 1.0}, 1.0, bits);
    expect_exact_atom({-1.0, 1.0}, double(0.450692087f), bits);
    expect_exact_atom({-1.0, 1.0}, 1e-30, bits);  // tiny: exact (the bits still fit) or...
    expect_exact_atom({-1e-12, 1e-12}, 3e-13, bits);
    // Kept as is: no atom, an atom outside the data, a constant channel, an atom that is not a number.
    for (const RmqRange data : {RmqRange{-1.0, 1.0}, RmqRange{0.25, 0.25}}) {
      for (const std::optional<double> atom :
           {std::optional<double>(), std::optional<double>(2.0), std::optional<double>(std::nan(""))}) {
        const RmqRange r = rmq_range_with_exact_value(data, atom, bits);
        EXPECT_EQ(r.lo, data.lo);
        EXPECT_EQ(r.hi, data.hi);
      }
    }
    const RmqRange constant = rmq_range_with_exact_value({0.25, 0.25}, 0.25, bits);
    EXPECT_EQ(constant.lo, 0.25);
    EXPECT_EQ(constant.hi, 0.25);
  }
}

struct FlatMap {
  std::string name;
  NormalMap map;
};

std::vector<FlatMap> flat_ground_maps() {
  std::vector<FlatMap> maps{{"gen scratches", generate_normal_map("scratches", {256, 256}, 3, Progress::silent())}};
  for (test::AtomMap& m : test::atom_maps(128))
    if (m.name == "90% one value" || m.name == "99% one value") maps.push_back({m.name, std::move(m.map)});
  return maps;
}

// Texels whose leaf is degenerate in both components (the texel and its 3 x 3 neighbours share the value) and
// equal to the map's most common such value: the flat ground.
std::vector<std::array<uint32_t, 2>> flat_ground(const NormalMap& m, Vec2& value) {
  std::map<std::pair<float, float>, size_t> count;
  std::vector<std::array<uint32_t, 2>> plateau;
  for (uint32_t row = 0; row < m.height; ++row)
    for (uint32_t x = 0; x < m.width; ++x)
      if (element_normal_reach(m, x, row) == Vec2::Zero()) ++count[{m.at(x, row).x(), m.at(x, row).y()}];
  size_t best = 0;
  for (const auto& [v, c] : count)
    if (c > best) best = c, value = Vec2(v.first, v.second);
  for (uint32_t row = 0; row < m.height; ++row)
    for (uint32_t x = 0; x < m.width; ++x)
      if (element_normal_reach(m, x, row) == Vec2::Zero() && m.at(x, row).x() == float(value.x()) &&
          m.at(x, row).y() == float(value.y()))
        plateau.push_back({x, row});
  return plateau;
}

TEST(RmqTable, FlatGroundLeavesReadBackExactly) {
  for (const FlatMap& f : flat_ground_maps())
    for (uint32_t bits : {16u, 8u}) {
      SCOPED_TRACE(f.name + " at " + std::to_string(bits) + " bits");
      Vec2 x0;
      const auto plateau = flat_ground(f.map, x0);
      ASSERT_GT(plateau.size(), f.map.texels.size() / 4);
      const RmqTable t = build_rmq_table(f.map, 32, bits, Progress::silent());
      const RmqTableView v = t.view();
      for (const auto& [x, row] : plateau) {
        const RmqBounds b = v.query(x, row, 1, 1);
        ASSERT_EQ(b.min_x, x0.x());
        ASSERT_EQ(b.max_x, x0.x());
        ASSERT_EQ(b.min_y, x0.y());
        ASSERT_EQ(b.max_y, x0.y());
      }
    }
}

TEST(GlintRangeQuery, PlateauNodesAreTheFlatGround_NoneLinearHistogram) {
  int all_plateau_nodes = 0;
  for (const FlatMap& f : flat_ground_maps()) {
    SCOPED_TRACE(f.name);
    Vec2 x0;
    flat_ground(f.map, x0);
    const BakedLut lut = bake_standardization_lut(f.map, kLutDefaultSize, Progress::silent());
    const RmqTable t = build_rmq_table(f.map, 32, 16, Progress::silent());
    const RmqTableView v = t.view();
    int plateau_nodes = 0;
    // (Variance blending moves flat ground itself: m + (x0 - m) / W varies with the weights' norm W.)
    for (const GlintBlendMode mode : {GlintBlendMode::none, GlintBlendMode::linear, GlintBlendMode::histogram}) {
      const GlintPointQuery point(f.map, 32, 1, mode, &lut.tables);
      const GlintRangeQuery range(point, v);
      const uint32_t h = range.target_side();
      for (int64_t p = 0; p < 16; ++p)
        for (uint32_t y = 0; y + 2 <= h; y += 2)
          for (uint32_t x = 0; x + 2 <= h; x += 2) {
            const TargetNode node{p % 4, p / 4, x, y, 2, 2};
            // A plateau node: every example square it reads holds only flat-ground leaves.
            bool plateau = true;
            for (int k = 0; k < 4 && plateau; ++k) {
              const auto e = range.example_texel(node.patch_i, node.patch_j, k, x, y);
              const RmqBounds b = v.query(e[0], e[1], 2, 2);
              plateau = b.min_x == x0.x() && b.max_x == x0.x() && b.min_y == x0.y() && b.max_y == x0.y();
            }
            if (!plateau) continue;
            ++plateau_nodes;
            const RmqBounds b = range.node_bounds(node);
            // The flat ground up to the rounding margin. Under histogram blending the field itself is
            // G^-1(G(x0) / W) on flat ground (G(x0), the atom's mid-rank value, is near but not at 0), a little
            // off x0 (1.3e-5 on the 99% map): the bound must stay narrower than what the P-NDF aggregates at
            // sigma_r = 0.005 (kGlintAggregateWidthSigmas sigma_r), the roughness of the benchmark.
            const double tolerance = mode == GlintBlendMode::histogram ? kGlintAggregateWidthSigmas * 0.005 : 1e-9;
            ASSERT_NEAR(b.min_x, x0.x(), tolerance);
            ASSERT_NEAR(b.max_x, x0.x(), tolerance);
            ASSERT_NEAR(b.min_y, x0.y(), tolerance);
            ASSERT_NEAR(b.max_y, x0.y(), tolerance);
          }
    }
    EXPECT_GT(plateau_nodes, 0);  // the 90% map's atoms sit in hashed places: few 2 x 2 blocks are all flat
    all_plateau_nodes += plateau_nodes;
  }
  EXPECT_GT(all_plateau_nodes, 1000);
}

}  // namespace
}  // namespace mbk
