// Simplification to the allowed cell configurations ([Parilov05] Sec. 4.1; libbake/crease/crease_network.h):
// random soups of 1,000 segments with coincident, crossing, collinear, lattice-aligned and vertex-crossing
// segments; each result checked against a brute-force intersection of every segment with every edge.
#include <gtest/gtest.h>

#include <bit>
#include <optional>
#include <random>

#include "libbake/core/parallel.h"
#include "libbake/crease/crease_network.h"
#include "tests/crease/crease_test_maps.h"

namespace mbk {
namespace {

// The allowed-configuration rules, checked directly on the field (junction words: by their records).
void expect_allowed(const CreaseField& f) {
  ASSERT_EQ(f.junction_points.size(), 2 * f.junction_cells.size());
  ASSERT_EQ(f.junction_spokes.size(), f.junction_cells.size());
  for (size_t n = 0; n < f.junction_cells.size(); ++n) {
    const uint32_t i = f.junction_cells[n] % f.cells_x(), j = f.junction_cells[n] / f.cells_x();
    if (n > 0) {
      EXPECT_GT(f.junction_cells[n], f.junction_cells[n - 1]);
    }
    EXPECT_EQ(f.segments[f.junction_cells[n]], kCreaseJunctionBit);
    const CreaseCellEdges c = crease_cell_edges(f, i, j);
    ASSERT_TRUE(c.junction);
    EXPECT_GE(std::popcount(unsigned(c.spokes & 0x0f)), 2);
    EXPECT_EQ((c.spokes >> 4) & ~c.spokes & 0x0f, 0);
    for (int k = 0; k < 4; ++k) {
      if ((c.spokes >> k) & 1u) {
        EXPECT_TRUE(c.crossing[k]) << i << "," << j << " spoke " << k;
      }
    }
    EXPECT_TRUE(crease_point_inside_edge_points(c, c.ex, c.ey, 0.5 * kCreaseMinT)) << i << "," << j;
  }
  for (float t : f.crossing_h) EXPECT_TRUE(t == kCreaseNoCrossing || (t >= kCreaseMinT && t <= 1 - kCreaseMinT)) << t;
  for (float t : f.crossing_v) EXPECT_TRUE(t == kCreaseNoCrossing || (t >= kCreaseMinT && t <= 1 - kCreaseMinT)) << t;
  for (uint32_t j = 0; j < f.cells_y(); ++j)
    for (uint32_t i = 0; i < f.cells_x(); ++i) {
      const CreaseCellEdges c = crease_cell_edges(f, i, j);
      if (c.mask == kCreaseJunctionBit) {
        EXPECT_TRUE(c.junction) << i << "," << j;
        continue;
      }
      EXPECT_EQ(c.mask & ~(kCreaseSegmentBits | kCreaseReversedBits), 0);
      EXPECT_LE(std::popcount(unsigned(c.mask & kCreaseSegmentBits)), 2) << i << "," << j;
      EXPECT_EQ((c.mask >> 8) & ~c.mask & kCreaseSegmentBits, 0);
      for (int bit = 0; bit < 6; ++bit)
        if (c.mask & (1u << bit)) {
          EXPECT_TRUE(c.crossing[kCreasePairFirst[bit]]) << i << "," << j << " bit " << bit;
          EXPECT_TRUE(c.crossing[kCreasePairSecond[bit]]) << i << "," << j << " bit " << bit;
        }
    }
}

// Brute force: the parameters t at which segment s meets the lattice edge from sample (i, j) along +x
// (horizontal) or +y; nullopt when it does not meet it in the edge's interior (properly, with margin).
std::optional<double> proper_crossing(const CurveSegment& s, double x0, double y0, bool horizontal, double margin) {
  // Edge: (x0, y0) + t e, t in [0, 1]; segment a + u (b - a).
  const Vec2 e = horizontal ? Vec2(1, 0) : Vec2(0, 1), d = s.b - s.a, r = Vec2(x0, y0) - s.a;
  const double den = d.x() * e.y() - d.y() * e.x();
  if (std::abs(den) < 1e-12) return std::nullopt;
  const double u = (r.x() * e.y() - r.y() * e.x()) / den, t = (r.x() * d.y() - r.y() * d.x()) / den;
  if (u <= margin || u >= 1 - margin || t <= margin || t >= 1 - margin) return std::nullopt;
  return t;
}

// Every edge that some input segment crosses properly (away from its ends and the edge's ends) has a
// crossing within the range of the input crossings on it; every crossing on an edge has an input segment
// meeting that edge (closed, with tolerance).
void expect_crossings_match_brute_force(const CreaseField& f, const std::vector<CurveSegment>& segments) {
  for (int horizontal = 0; horizontal < 2; ++horizontal) {
    const uint32_t ex = horizontal ? f.cells_x() : f.samples_x(), ey = horizontal ? f.samples_y() : f.cells_y();
    for (uint32_t j = 0; j < ey; ++j)
      for (uint32_t i = 0; i < ex; ++i) {
        const float t = horizontal ? f.crossing_h[f.h_edge_index(i, j)] : f.crossing_v[f.v_edge_index(i, j)];
        // The merged crossing is a mean of crossings, so it lies between the smallest and the largest place
        // where a segment meets the edge (closed: ends, vertices and lattice-aligned segments included).
        double lo = 2, hi = -1;
        bool proper = false;
        for (const CurveSegment& s : segments) {
          if (proper_crossing(s, i - 0.5, j - 0.5, horizontal, 1e-9)) proper = true;
          if (auto c = proper_crossing(s, i - 0.5, j - 0.5, horizontal, -1e-9)) {
            const double clamped = std::clamp(*c, double(kCreaseMinT), 1.0 - kCreaseMinT);
            lo = std::min(lo, clamped), hi = std::max(hi, clamped);
          }
        }
        const std::string at =
            std::string(horizontal ? "h" : "v") + " edge " + std::to_string(i) + "," + std::to_string(j);
        if (proper) {
          EXPECT_NE(t, kCreaseNoCrossing) << at;
        }
        if (t != kCreaseNoCrossing) {
          ASSERT_GE(hi, 0.0) << at << ": a crossing where no segment meets the edge";
          EXPECT_GE(t, lo - 1e-6) << at;
          EXPECT_LE(t, hi + 1e-6) << at;
        }
      }
  }
}

std::vector<CurveSegment> random_soup(uint32_t w, uint32_t h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(0.0, w), uy(0.0, h);
  std::uniform_int_distribution<int> kind(0, 5), ix(0, int(w)), iy(0, int(h));
  std::vector<CurveSegment> out;
  while (out.size() < 1000) {
    CurveSegment s{{ux(rng), uy(rng)}, {ux(rng), uy(rng)}};
    switch (kind(rng)) {
      case 0:  // coincident with an earlier segment (same or reversed)
        if (!out.empty()) s = out[size_t(rng() % out.size())];
        if (rng() % 2) std::swap(s.a, s.b);
        break;
      case 1:  // collinear with an earlier one, overlapping part of it
        if (!out.empty()) {
          const CurveSegment& o = out[size_t(rng() % out.size())];
          s = {o.a + 0.3 * (o.b - o.a), o.a + 0.8 * (o.b - o.a)};
        }
        break;
      case 2:  // along a lattice line x = i - 0.5 (cell edges)
        s.a.x() = s.b.x() = std::clamp(ix(rng) - 0.5, 0.0, double(w));
        break;
      case 3:  // along a lattice line y = j - 0.5
        s.a.y() = s.b.y() = std::clamp(iy(rng) - 0.5, 0.0, double(h));
        break;
      case 4:  // through lattice vertices (diagonal between sample positions)
        s.a = Vec2(std::clamp(ix(rng) - 0.5, 0.0, double(w)), std::clamp(iy(rng) - 0.5, 0.0, double(h)));
        s.b = s.a + Vec2(3, 3);
        s.b = s.b.cwiseMin(Vec2(w, h));
        break;
      default:
        break;
    }
    if (s.a != s.b) out.push_back(s);
  }
  return out;
}

TEST(CreaseNetwork, RandomSoupsGiveOnlyAllowedConfigurations) {
  for (uint32_t seed : {1u, 2u, 3u}) {
    const uint32_t w = 37, h = 23;  // non-square, non-power-of-two
    const std::vector<CurveSegment> soup = random_soup(w, h, seed);
    CreaseField f;
    f.allocate(w, h);
    const SimplifyStatistics s = simplify_curves(test::curves_of(soup), f);
    EXPECT_EQ(s.input_segments, 1000u);
    EXPECT_GT(s.merged_edges, 0u);
    EXPECT_GT(s.deleted_segments, 0u);  // a soup this dense must exercise the two-per-cell rule
    expect_allowed(f);
    expect_crossings_match_brute_force(f, soup);
  }
}

TEST(CreaseNetwork, SameSignatureAndStatisticsWhateverTheThreadCount) {
  // 1,000 curves are walked in parallel chunks; merged crossings are sums in walk order, so any reordering of
  // coincident segments' records across chunks would change their last bits.
  const uint32_t w = 37, h = 23;
  const CurveSet soup = test::curves_of(random_soup(w, h, 4));
  CreaseField one, two;
  one.allocate(w, h);
  two.allocate(w, h);
  set_thread_count(1);
  const SimplifyStatistics s1 = simplify_curves(soup, one);
  set_thread_count(2);
  const SimplifyStatistics s2 = simplify_curves(soup, two);
  set_thread_count(0);
  EXPECT_GT(s1.merged_edges, 0u);
  EXPECT_EQ(s1.to_json(), s2.to_json());
  EXPECT_EQ(one.crossing_h, two.crossing_h);
  EXPECT_EQ(one.crossing_v, two.crossing_v);
  EXPECT_EQ(one.segments, two.segments);
}

TEST(CreaseNetwork, SingleSegmentCrossingsAreExact) {
  const CurveSegment s{{0.2, 1.3}, {9.7, 6.1}};
  CreaseField f;
  f.allocate(10, 8);
  simplify_curves(test::curves_of({s}), f);
  expect_allowed(f);
  // Every stored crossing lies on the input line to float rounding.
  for (const CurveSegment& n : network_segments(f)) {
    EXPECT_NEAR(test::signed_line_distance(s.a, s.b, n.a), 0.0, 1e-6);
    EXPECT_NEAR(test::signed_line_distance(s.a, s.b, n.b), 0.0, 1e-6);
  }
  expect_crossings_match_brute_force(f, {s});
}

TEST(CreaseNetwork, SegmentAlongLatticeLineRunsInTheCellsRightOfIt) {
  CreaseField f;
  f.allocate(8, 8);
  simplify_curves(test::curves_of({{{3.5, 0.2}, {3.5, 7.8}}}), f);  // x = 3.5 is lattice line i = 4
  expect_allowed(f);
  for (uint32_t j = 1; j <= 7; ++j) {  // horizontal edges crossed at t = 0, clamped
    EXPECT_EQ(f.crossing_h[f.h_edge_index(4, j)], kCreaseMinT) << j;
    EXPECT_EQ(f.crossing_h[f.h_edge_index(3, j)], kCreaseNoCrossing) << j;
  }
  for (uint32_t j = 1; j <= 6; ++j) EXPECT_EQ(f.segments[f.cell_index(4, j)] & kCreaseSegmentBits, 1u << 4) << j;
}

TEST(CreaseNetwork, SegmentThroughLatticeVertex) {
  CreaseField f;
  f.allocate(8, 8);
  simplify_curves(test::curves_of({{{0.7, 0.7}, {6.3, 6.3}}}), f);  // passes the vertices (i - 0.5, i - 0.5)
  expect_allowed(f);
  EXPECT_GT(network_segments(f).size(), 5u);
}

// A curve through a sample crosses the two edges beside it at their ends. Where one of those edges also carries
// another curve's crossing, the sample's crossing yields (the other is not moved towards the sample) and the piece
// that only touched the cell at that corner is dropped (it would now cut a large triangle off the cell).
TEST(CreaseNetwork, CrossingAtASampleYieldsToAnotherCurvesCrossing) {
  CreaseField f;
  f.allocate(8, 8);
  CurveSet curves =
      test::curves_of({{{0.2, 2.25}, {7.8, 2.25}},      // horizontal: crosses x = 3.5 at t = 0.75 of cell row 2
                       {{2.25, 1.25}, {5.75, 4.75}}});  // 45 degrees through the sample (4, 3) at (3.5, 2.5)
  simplify_curves(curves, f);
  expect_allowed(f);
  // The edge from sample (4, 2) to (4, 3) keeps the horizontal curve's crossing exactly.
  EXPECT_EQ(f.crossing_v[f.v_edge_index(4, 2)], 0.75f);
  // Cell (4, 2), right of that edge, holds the horizontal segment only (P1 - P3), not a cut of its corner C3.
  EXPECT_EQ(f.segments[f.cell_index(4, 2)] & kCreaseSegmentBits, 1u << 5);
  // The diagonal keeps its segments in the cells it runs through between samples.
  EXPECT_NE(f.segments[f.cell_index(4, 3)] & kCreaseSegmentBits, 0);
}

TEST(CreaseNetwork, CoincidentSegmentsMergeToOne) {
  CreaseField f;
  f.allocate(8, 8);
  const SimplifyStatistics s =
      simplify_curves(test::curves_of({{{0.2, 1.2}, {7.6, 3.1}}, {{7.6, 3.1}, {0.2, 1.2}}}), f);
  expect_allowed(f);
  EXPECT_LT(s.max_merge_shift, 1e-7);  // float rounding of the stored crossing
  EXPECT_EQ(s.merged_edges, s.crossed_edges);
}

TEST(CreaseNetwork, ThreeSegmentsInACellKeepTwo) {
  CreaseField f;
  f.allocate(4, 4);
  // Three lines through cell (2, 2) ([1.5, 2.5]^2), each crossing a different pair of its edges.
  const SimplifyStatistics s = simplify_curves(
      test::curves_of({{{1.0, 1.7}, {3.0, 1.7}}, {{1.7, 1.0}, {1.7, 3.0}}, {{1.6, 3.0}, {3.0, 1.6}}}), f);
  expect_allowed(f);
  EXPECT_GE(s.deleted_segments, 1u);
}

TEST(CreaseNetwork, PolylineCornerInsideCellKeepsASegment) {
  CreaseField f;
  f.allocate(8, 8);
  CurveSet c;
  c.curves.push_back({{{0.2, 3.1}, {4.1, 3.9}, {4.6, 7.8}}, false, "test"});  // corner inside cell (4, 4)
  simplify_curves(c, f);
  expect_allowed(f);
  EXPECT_NE(f.segments[f.cell_index(4, 4)] & kCreaseSegmentBits, 0);
}

// Three curves ending at one point inside a cell, leaving by three edges: the cell is a junction at that point with
// one spoke per edge, each in its curve's direction; the distance vanishes at the point.
TEST(CreaseNetwork, CurvesEndingAtOnePointMakeAJunctionThere) {
  CreaseField f;
  f.allocate(8, 8);
  const Vec2 j(4.3, 4.2);  // inside cell (4, 4): [3.5, 4.5]^2, cell-local (0.8, 0.7)
  const SimplifyStatistics s = simplify_curves(test::curves_of({{j, {4.3, 0.0}}, {j, {8.0, 4.2}}, {{0.0, 8.0}, j}}), f);
  expect_allowed(f);
  EXPECT_EQ(s.junction_cells, 1u);
  ASSERT_EQ(f.junction_cells, std::vector<uint32_t>{uint32_t(f.cell_index(4, 4))});
  EXPECT_NEAR(f.junction_points[0], 0.8, 1e-6);
  EXPECT_NEAR(f.junction_points[1], 0.7, 1e-6);
  // Spokes to the top edge (0) and the right edge (1) run out of the junction; the third curve comes in by the
  // bottom edge (2): from (0, 8) it reaches the cell's bottom edge at x = 3.96.
  EXPECT_EQ(f.junction_spokes[0], 0x01 | 0x02 | 0x04 | (0x04 << 4));
  double nearest = 1e9;
  for (const CurveSegment& seg : network_segments(f))
    nearest = std::min({nearest, (seg.a - j).norm(), (seg.b - j).norm()});
  EXPECT_LT(nearest, 1e-6);
}

// A junction point that the cell's edge points leave outside their quadrilateral (here near corner C0, while the
// creases leave by the right and bottom edges) is moved inside it, towards the edge points' centroid.
TEST(CreaseNetwork, JunctionOutsideTheEdgePointsIsMovedInside) {
  CreaseField f;
  f.allocate(8, 8);
  const Vec2 j(3.55, 3.56);  // cell (4, 4), cell-local (0.05, 0.06): outside the line P3 P0 (u + v = 0.5)
  simplify_curves(test::curves_of({{j, {8.0, 3.9}}, {j, {3.9, 8.0}}, {j, {8.0, 8.0}}}), f);
  expect_allowed(f);
  ASSERT_EQ(f.junction_cells.size(), 1u);
  const double u = f.junction_points[0], v = f.junction_points[1];
  EXPECT_GT(u + v, 0.5);         // inside
  EXPECT_LT(u + v, 0.5 + 0.01);  // and no farther than it had to go
}

TEST(CreaseNetwork, SegmentsMeetingInsideACellAreJoined) {
  // A panel corner: an outline edge from above, one from the left and the mitre, listed as three separate
  // curves ending at (4.2, 4.3), inside cell (4, 4).
  CreaseField f;
  f.allocate(8, 8);
  const SimplifyStatistics s = simplify_curves(
      test::curves_of({{{4.2, 0.0}, {4.2, 4.3}}, {{0.0, 4.3}, {4.2, 4.3}}, {{1.1, 1.2}, {4.2, 4.3}}}), f);
  expect_allowed(f);
  // A junction with a spoke to the top edge and one to the left edge (the mitre enters by the same edge as one
  // outline: two distinct edges), nothing deleted.
  EXPECT_EQ(f.segments[f.cell_index(4, 4)], kCreaseJunctionBit);
  ASSERT_EQ(f.junction_spokes.size(), 1u);
  EXPECT_EQ(f.junction_spokes[0] & 0x0f, 0x01 | 0x08);
  EXPECT_EQ(s.deleted_segments, 0u);
  // Two separate segments merely touching at a point of a cell edge are not a junction inside a cell.
  CreaseField g;
  g.allocate(8, 8);
  simplify_curves(test::curves_of({{{0.0, 2.2}, {3.5, 2.2}}}), g);
  expect_allowed(g);
}

TEST(CreaseNetwork, ClosedCurveJoinsItsLastPieceToItsFirst) {
  CreaseField f;
  f.allocate(8, 8);
  CurveSet c;
  c.curves.push_back({{{2.1, 2.2}, {6.1, 2.3}, {5.8, 6.2}, {2.2, 5.9}}, true, "test"});
  simplify_curves(c, f);
  expect_allowed(f);
  EXPECT_NE(f.segments[f.cell_index(2, 2)] & kCreaseSegmentBits, 0);  // the cell of the first point
}

TEST(CreaseNetwork, CurveInsideOneCellLeavesNothing) {
  CreaseField f;
  f.allocate(4, 4);
  const SimplifyStatistics s = simplify_curves(test::curves_of({{{1.6, 1.6}, {2.4, 2.4}}}), f);
  EXPECT_EQ(s.crossed_edges, 0u);
  EXPECT_TRUE(network_segments(f).empty());
}

TEST(CreaseNetwork, OneByOneMap) {
  CreaseField f;
  f.allocate(1, 1);
  simplify_curves(test::curves_of({{{0.0, 0.0}, {1.0, 1.0}}}), f);
  expect_allowed(f);
  EXPECT_FALSE(network_segments(f).empty());
}

}  // namespace
}  // namespace mbk
