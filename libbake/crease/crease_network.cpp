// Simplifying discontinuity curves to the allowed cell configurations (see crease_network.h).
#include "libbake/crease/crease_network.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace mbk {
namespace {

struct EdgeCrossings {
  double sum = 0.0, min = 0.0, max = 0.0;
  uint32_t count = 0;
  void add(double t) {
    min = count ? std::min(min, t) : t;
    max = count ? std::max(max, t) : t;
    sum += t;
    ++count;
  }
};

struct CellPieces {
  std::array<uint32_t, 6> count{};
  std::array<int64_t, 6> direction{};  // +1 per piece running first -> second edge of the pair, -1 reversed
};

struct LineCrossing {
  double s;       // parameter along the segment
  bool vertical;  // crosses a vertical lattice line
};

double clamp_t(double t) { return std::clamp(t, double(kCreaseMinT), 1.0 - double(kCreaseMinT)); }

int64_t cell_of(double x, uint32_t cells) {
  return std::clamp<int64_t>(int64_t(std::floor(x + 0.5)), 0, int64_t(cells) - 1);
}

}  // namespace

nlohmann::json SimplifyStatistics::to_json() const {
  return {{"input_segments", input_segments},    {"input_crossings", input_crossings},
          {"crossed_edges", crossed_edges},      {"merged_edges", merged_edges},
          {"max_merge_shift", max_merge_shift},  {"cells_with_segments", cells_with_segments},
          {"deleted_segments", deleted_segments}};
}

SimplifyStatistics simplify_curves(const CurveSet& curves, CreaseField& field) {
  SimplifyStatistics stats;
  std::vector<EdgeCrossings> h(field.crossing_h.size()), v(field.crossing_v.size());
  std::vector<CellPieces> cells(field.segments.size());
  std::vector<LineCrossing> crossings;
  int64_t cx = 0, cy = 0;  // the walk's current cell
  int entry = -1;          // the edge through which the walk entered it (-1: the curve starts in it)
  int first_exit = -1;     // the edge through which the curve left its first cell
  struct CurveEnd {
    int64_t cell_x, cell_y;
    int edge;       // the edge through which the curve leaves (outgoing) or enters the cell of its end point
    bool outgoing;  // the curve starts here
  };
  std::map<std::pair<double, double>, std::vector<CurveEnd>> ends;  // by end point
  auto add_piece = [&](int from, int to) {
    const int bit = crease_pair_bit(from, to);
    if (bit < 0) return;  // left through the edge it came in by (a polyline folding back): no segment
    CellPieces& p = cells[field.cell_index(uint32_t(cx), uint32_t(cy))];
    ++p.count[size_t(bit)];
    p.direction[size_t(bit)] += kCreasePairFirst[bit] == from ? 1 : -1;
  };
  auto walk = [&](const CurveSegment& seg) {
    const double ax = seg.a.x(), ay = seg.a.y(), dx = seg.b.x() - ax, dy = seg.b.y() - ay;
    const int64_t bx = cell_of(seg.b.x(), field.cells_x()), by = cell_of(seg.b.y(), field.cells_y());
    crossings.clear();
    // Lattice line i (sample column i) is x = i - 0.5; moving from cell c to c + 1 crosses line c + 1.
    for (int64_t c = std::min(cx, bx); c < std::max(cx, bx); ++c) crossings.push_back({(c + 0.5 - ax) / dx, true});
    for (int64_t c = std::min(cy, by); c < std::max(cy, by); ++c) crossings.push_back({(c + 0.5 - ay) / dy, false});
    // Order along the segment; at a lattice vertex the perturbation crosses the vertical line first when dx > 0.
    std::sort(crossings.begin(), crossings.end(), [&](const LineCrossing& p, const LineCrossing& q) {
      if (p.s != q.s) return p.s < q.s;
      if (p.vertical == q.vertical) return false;
      return p.vertical == (dx > 0.0);
    });
    for (const LineCrossing& c : crossings) {
      const double x = ax + c.s * dx, y = ay + c.s * dy;
      int exit, next_entry;
      int64_t nx = cx, ny = cy;
      if (c.vertical) {
        const bool right = dx > 0.0;
        exit = right ? 1 : 3;
        next_entry = right ? 3 : 1;
        nx += right ? 1 : -1;
        v[field.v_edge_index(uint32_t(right ? cx + 1 : cx), uint32_t(cy))].add(clamp_t(y - (double(cy) - 0.5)));
      } else {
        const bool down = dy > 0.0;
        exit = down ? 2 : 0;
        next_entry = down ? 0 : 2;
        ny += down ? 1 : -1;
        h[field.h_edge_index(uint32_t(cx), uint32_t(down ? cy + 1 : cy))].add(clamp_t(x - (double(cx) - 0.5)));
      }
      ++stats.input_crossings;
      if (entry >= 0) add_piece(entry, exit);
      if (first_exit < 0 && entry < 0) first_exit = exit;
      cx = nx;
      cy = ny;
      entry = next_entry;
    }
  };
  for (const CurvePolyline& curve : curves.curves) {
    // A polyline is walked as one path: a vertex inside a cell joins the piece coming in to the piece going
    // out, so the cell keeps a segment from its entry edge to its exit edge.
    CurveSet one;
    one.curves.push_back(curve);
    const std::vector<CurveSegment> segments = curve_segments(one);
    stats.input_segments += segments.size();
    cx = cell_of(curve.points.front().x(), field.cells_x());
    cy = cell_of(curve.points.front().y(), field.cells_y());
    const int64_t start_x = cx, start_y = cy;
    entry = -1;
    first_exit = -1;
    for (const CurveSegment& seg : segments) walk(seg);
    // A closed curve back in its first cell joins its last piece to its first.
    if (curve.closed && entry >= 0 && first_exit >= 0 && cx == start_x && cy == start_y) {
      add_piece(entry, first_exit);
    } else {  // an open curve's ends inside cells, for the junctions below
      if (first_exit >= 0)
        ends[{curve.points.front().x(), curve.points.front().y()}].push_back({start_x, start_y, first_exit, true});
      if (entry >= 0) ends[{curve.points.back().x(), curve.points.back().y()}].push_back({cx, cy, entry, false});
    }
  }
  // Junctions: curves whose ends are the same point join there. Every pair of their edges (distinct) becomes a
  // piece of the junction's cell, from an incoming curve to an outgoing one; the two-per-cell rule below keeps
  // the best supported. (Deviation [Parilov05]: the paper converts segments one by one, so where separately
  // listed segments meet inside a cell - a panel's corner and its mitre - the cell gets no segment and
  // interpolates across the creases; test: CreaseNetwork.SegmentsMeetingInsideACellAreJoined.)
  for (const auto& [point, at] : ends)
    for (size_t a = 0; a < at.size(); ++a)
      for (size_t b = a + 1; b < at.size(); ++b) {
        const CurveEnd& p = at[a].outgoing && !at[b].outgoing ? at[b] : at[a];
        const CurveEnd& q = &p == &at[a] ? at[b] : at[a];
        cx = p.cell_x, cy = p.cell_y;
        add_piece(p.edge, q.edge);
      }
  auto merge = [&](const std::vector<EdgeCrossings>& in, std::vector<float>& out) {
    for (size_t e = 0; e < in.size(); ++e) {
      if (!in[e].count) continue;
      const float t = float(clamp_t(in[e].sum / in[e].count));
      out[e] = std::clamp(t, kCreaseMinT, 1.0f - kCreaseMinT);
      ++stats.crossed_edges;
      if (in[e].count > 1) ++stats.merged_edges;
      stats.max_merge_shift = std::max({stats.max_merge_shift, std::abs(in[e].min - t), std::abs(in[e].max - t)});
    }
  };
  merge(h, field.crossing_h);
  merge(v, field.crossing_v);
  for (size_t c = 0; c < cells.size(); ++c) {
    std::array<int, 6> order = {0, 1, 2, 3, 4, 5};
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return cells[c].count[size_t(a)] > cells[c].count[size_t(b)]; });
    uint16_t mask = 0;
    uint32_t kept = 0;
    for (int bit : order) {
      if (!cells[c].count[size_t(bit)]) break;
      if (kept == kCreaseMaxSegmentsPerCell) {
        ++stats.deleted_segments;
        continue;
      }
      mask |= uint16_t(1u << bit);
      if (cells[c].direction[size_t(bit)] < 0) mask |= uint16_t(1u << (8 + bit));
      ++kept;
    }
    field.segments[c] = mask;
    if (mask) ++stats.cells_with_segments;
  }
  return stats;
}

std::vector<CurveSegment> network_segments(const CreaseField& field) {
  std::vector<CurveSegment> out;
  for (uint32_t j = 0; j < field.cells_y(); ++j)
    for (uint32_t i = 0; i < field.cells_x(); ++i) {
      const CreaseCellEdges c = crease_cell_edges(field, i, j);
      if (!(c.mask & kCreaseSegmentBits)) continue;
      const Vec2 origin(double(i) - 0.5, double(j) - 0.5);
      for (int bit = 0; bit < 6; ++bit) {
        if (!(c.mask & (1u << bit))) continue;
        const int a = kCreasePairFirst[bit], b = kCreasePairSecond[bit];
        Vec2 pa = origin + Vec2(c.px[a], c.py[a]), pb = origin + Vec2(c.px[b], c.py[b]);
        if (c.mask & (1u << (8 + bit))) std::swap(pa, pb);
        out.push_back({pa, pb});
      }
    }
  return out;
}

}  // namespace mbk
