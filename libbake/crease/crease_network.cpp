// Simplifying discontinuity curves to the allowed cell configurations (see crease_network.h).
#include "libbake/crease/crease_network.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>

#include "libbake/core/grouped_by_key.h"
#include "libbake/core/parallel.h"

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

// One crossing of a cell edge by a curve, as the walk meets it.
struct EdgeCrossing {
  size_t edge;
  double t;
};

// One piece of curve through a cell, from one of its edges to another, as the walk meets it.
struct CellPiece {
  uint32_t cell;     // cells number at most (16384 + 1)^2 (formats/crease_field.h)
  int8_t bit;        // the edge pair (crease_pair_bit)
  int8_t direction;  // +1 running from the pair's first edge to its second, -1 reversed
  bool at_corner;    // the curve only touches the cell at the corner between the pair's edges (through its sample)
};

struct LineCrossing {
  double s;       // parameter along the segment
  bool vertical;  // crosses a vertical lattice line
};

double clamp_t(double t) { return std::clamp(t, double(kCreaseMinT), 1.0 - double(kCreaseMinT)); }

// A crossing clamped to the end of its edge: the curve passes (within kCreaseMinT) through the lattice sample there.
bool at_sample(double clamped_t) { return clamped_t <= double(kCreaseMinT) || clamped_t >= 1.0 - double(kCreaseMinT); }

int64_t cell_of(double x, uint32_t cells) {
  return std::clamp<int64_t>(int64_t(std::floor(x + 0.5)), 0, int64_t(cells) - 1);
}

}  // namespace

nlohmann::json SimplifyStatistics::to_json() const {
  return {{"input_segments", input_segments},     {"input_crossings", input_crossings},
          {"crossed_edges", crossed_edges},       {"merged_edges", merged_edges},
          {"max_merge_shift", max_merge_shift},   {"cells_with_segments", cells_with_segments},
          {"deleted_segments", deleted_segments}, {"junction_cells", junction_cells}};
}

namespace {

// A point inside a cell where creases meet: the cell, the point in cell-local coordinates, and its spokes in the
// junction_spokes encoding (formats/crease_field.h).
struct Junction {
  size_t cell;
  double u, v;
  uint8_t spokes;
};

// The end of an open curve inside a cell, for the junctions.
struct CurveEnd {
  int64_t cell_x, cell_y;
  int edge;       // the edge through which the curve leaves (outgoing) or enters the cell of its end point
  bool outgoing;  // the curve starts here
};

// Walks the curves through the cells: records every crossing of a cell edge and every piece of curve through a
// cell, from the edge it entered by to the edge it left by, in the order it meets them (lists rather than per-cell
// accumulators: most cells see no curve), and where open curves end.
class CurveWalk {
 public:
  explicit CurveWalk(const CreaseField& field) : field_(field) {}

  // A polyline is walked as one path: a vertex inside a cell joins the piece coming in to the piece going out, so
  // the cell keeps a segment from its entry edge to its exit edge.
  void walk_curve(const CurvePolyline& curve, SimplifyStatistics& stats) {
    CurveSet one;
    one.curves.push_back(curve);
    const std::vector<CurveSegment> segments = curve_segments(one);
    stats.input_segments += segments.size();
    cx_ = cell_of(curve.points.front().x(), field_.cells_x());
    cy_ = cell_of(curve.points.front().y(), field_.cells_y());
    const int64_t start_x = cx_, start_y = cy_;
    entry_ = -1;
    first_exit_ = -1;
    entry_sample_ = kNoSample;
    for (const CurveSegment& seg : segments) walk_segment(seg, stats);
    // A closed curve back in its first cell joins its last piece to its first.
    if (curve.closed && entry_ >= 0 && first_exit_ >= 0 && cx_ == start_x && cy_ == start_y) {
      add_piece(cx_, cy_, entry_, first_exit_);
    } else {  // an open curve's ends inside cells, for the junctions
      if (first_exit_ >= 0)
        ends[{curve.points.front().x(), curve.points.front().y()}].push_back({start_x, start_y, first_exit_, true});
      if (entry_ >= 0) ends[{curve.points.back().x(), curve.points.back().y()}].push_back({cx_, cy_, entry_, false});
    }
  }

  // Junctions: curves whose ends are the same point join there. Every pair of their edges (distinct) becomes a
  // piece of the junction's cell, from an incoming curve to an outgoing one; the two-per-cell rule keeps the best
  // supported. (Deviation [Parilov05]: the paper converts segments one by one, so where separately listed segments
  // meet inside a cell - a panel's corner and its mitre - the cell gets no segment and interpolates across the
  // creases; test: CreaseNetwork.SegmentsMeetingInsideACellAreJoined.)
  //
  // Where the ends leave by two or more distinct edges, the point is also a junction candidate: its cell can keep
  // every one of those creases as a spoke from the point itself (place_junctions).
  void join_curve_ends() {
    for (const auto& [point, at] : ends) {
      for (size_t a = 0; a < at.size(); ++a)
        for (size_t b = a + 1; b < at.size(); ++b) {
          const CurveEnd& p = at[a].outgoing && !at[b].outgoing ? at[b] : at[a];
          const CurveEnd& q = &p == &at[a] ? at[b] : at[a];
          add_piece(p.cell_x, p.cell_y, p.edge, q.edge);
        }
      Junction j{field_.cell_index(uint32_t(at.front().cell_x), uint32_t(at.front().cell_y)),
                 point.first - (double(at.front().cell_x) - 0.5), point.second - (double(at.front().cell_y) - 0.5), 0};
      for (const CurveEnd& end : at)
        if (!((j.spokes >> end.edge) & 1u))  // the first end by an edge sets the spoke's direction
          j.spokes |= uint8_t((1u << end.edge) | (end.outgoing ? 0u : 1u << (4 + end.edge)));
      if (std::popcount(unsigned(j.spokes & 0x0f)) >= 2) junctions.push_back(j);
    }
  }

  std::vector<EdgeCrossing> h, v;  // crossings of horizontal / vertical cell edges
  std::vector<CellPiece> pieces;
  std::map<std::pair<double, double>, std::vector<CurveEnd>> ends;  // by end point
  std::vector<Junction> junctions;                                  // candidates, by end point

 private:
  void add_piece(int64_t x, int64_t y, int from, int to, bool at_corner = false) {
    const int bit = crease_pair_bit(from, to);
    if (bit < 0) return;  // left through the edge it came in by (a polyline folding back): no segment
    pieces.push_back({uint32_t(field_.cell_index(uint32_t(x), uint32_t(y))), int8_t(bit),
                      int8_t(kCreasePairFirst[bit] == from ? 1 : -1), at_corner});
  }

  void walk_segment(const CurveSegment& seg, SimplifyStatistics& stats) {
    const double ax = seg.a.x(), ay = seg.a.y(), dx = seg.b.x() - ax, dy = seg.b.y() - ay;
    const int64_t bx = cell_of(seg.b.x(), field_.cells_x()), by = cell_of(seg.b.y(), field_.cells_y());
    crossings_.clear();
    // Lattice line i (sample column i) is x = i - 0.5; moving from cell c to c + 1 crosses line c + 1.
    for (int64_t c = std::min(cx_, bx); c < std::max(cx_, bx); ++c) crossings_.push_back({(c + 0.5 - ax) / dx, true});
    for (int64_t c = std::min(cy_, by); c < std::max(cy_, by); ++c) crossings_.push_back({(c + 0.5 - ay) / dy, false});
    // Order along the segment; at a lattice vertex the perturbation crosses the vertical line first when dx > 0.
    std::sort(crossings_.begin(), crossings_.end(), [&](const LineCrossing& p, const LineCrossing& q) {
      if (p.s != q.s) return p.s < q.s;
      if (p.vertical == q.vertical) return false;
      return p.vertical == (dx > 0.0);
    });
    for (const LineCrossing& c : crossings_) {
      const double x = ax + c.s * dx, y = ay + c.s * dy;
      int exit, next_entry;
      int64_t nx = cx_, ny = cy_;
      LatticeSample sample = kNoSample;  // the sample the crossing is at, if any
      if (c.vertical) {
        const bool right = dx > 0.0;
        exit = right ? 1 : 3;
        next_entry = right ? 3 : 1;
        nx += right ? 1 : -1;
        const double t = clamp_t(y - (double(cy_) - 0.5));
        v.push_back({field_.v_edge_index(uint32_t(right ? cx_ + 1 : cx_), uint32_t(cy_)), t});
        if (at_sample(t)) sample = {right ? cx_ + 1 : cx_, t < 0.5 ? cy_ : cy_ + 1};
      } else {
        const bool down = dy > 0.0;
        exit = down ? 2 : 0;
        next_entry = down ? 0 : 2;
        ny += down ? 1 : -1;
        const double t = clamp_t(x - (double(cx_) - 0.5));
        h.push_back({field_.h_edge_index(uint32_t(cx_), uint32_t(down ? cy_ + 1 : cy_)), t});
        if (at_sample(t)) sample = {t < 0.5 ? cx_ : cx_ + 1, down ? cy_ + 1 : cy_};
      }
      ++stats.input_crossings;
      // A curve through a sample crosses both edges beside it, passing through the cell between them only at that
      // corner: the piece is marked (see corner_piece_kept).
      if (entry_ >= 0) add_piece(cx_, cy_, entry_, exit, sample != kNoSample && sample == entry_sample_);
      if (first_exit_ < 0 && entry_ < 0) first_exit_ = exit;
      cx_ = nx;
      cy_ = ny;
      entry_ = next_entry;
      entry_sample_ = sample;
    }
  }

  using LatticeSample = std::pair<int64_t, int64_t>;  // sample (i, j)
  static constexpr LatticeSample kNoSample = {-1, -1};

  const CreaseField& field_;
  std::vector<LineCrossing> crossings_;
  LatticeSample entry_sample_ = kNoSample;  // the sample the walk entered the current cell at, if any
  int64_t cx_ = 0, cy_ = 0;                 // the walk's current cell
  int entry_ = -1;                          // the edge through which the walk entered it (-1: the curve starts in it)
  int first_exit_ = -1;                     // the edge through which the curve left its first cell
};

// Each crossed edge's crossing: the mean of the curves' crossings there (merged when several cross it), summed in
// the walk's order. Blocks of edges in parallel, their statistics added in block order.
void merge_edge_crossings(const GroupedByKey<EdgeCrossing>& by_edge, std::vector<float>& out,
                          SimplifyStatistics& stats) {
  constexpr size_t kBlock = 4096;
  std::vector<SimplifyStatistics> block_stats((out.size() + kBlock - 1) / kBlock);
  parallel_for(0, int64_t(block_stats.size()), [&](int64_t b) {
    SimplifyStatistics& s = block_stats[size_t(b)];
    for (size_t e = size_t(b) * kBlock; e < std::min(out.size(), size_t(b + 1) * kBlock); ++e) {
      if (by_edge.begin(e) == by_edge.end(e)) continue;
      // A crossing at a sample yields to the edge's other crossings: the sample lies on a curve, so the
      // reconstruction does not take its normal for either side (formats/crease_reconstruction.h), and merging
      // would move a crossing inside the edge towards the sample.
      bool inside = false;
      for (size_t r = by_edge.begin(e); r < by_edge.end(e); ++r) inside |= !at_sample(by_edge.records[r].t);
      EdgeCrossings in;
      for (size_t r = by_edge.begin(e); r < by_edge.end(e); ++r)
        if (!inside || !at_sample(by_edge.records[r].t)) in.add(by_edge.records[r].t);
      const float t = float(clamp_t(in.sum / in.count));
      out[e] = std::clamp(t, kCreaseMinT, 1.0f - kCreaseMinT);
      ++s.crossed_edges;
      if (in.count > 1) ++s.merged_edges;
      s.max_merge_shift = std::max({s.max_merge_shift, std::abs(in.min - t), std::abs(in.max - t)});
    }
  });
  for (const SimplifyStatistics& s : block_stats) {
    stats.crossed_edges += s.crossed_edges;
    stats.merged_edges += s.merged_edges;
    stats.max_merge_shift = std::max(stats.max_merge_shift, s.max_merge_shift);
  }
}

// Each cell's signature: its best-supported edge pairs (the most pieces; ties in pair order), at most
// kCreaseMaxSegmentsPerCell of them, each with the direction most of its pieces ran; counts the pairs it deletes.
uint16_t cell_signature(const CellPieces& cell, uint64_t& deleted_segments) {
  std::array<int, 6> order = {0, 1, 2, 3, 4, 5};
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return cell.count[size_t(a)] > cell.count[size_t(b)]; });
  uint16_t mask = 0;
  uint32_t kept = 0;
  for (int bit : order) {
    if (!cell.count[size_t(bit)]) break;
    if (kept == kCreaseMaxSegmentsPerCell) {
      ++deleted_segments;
      continue;
    }
    mask |= uint16_t(1u << bit);
    if (cell.direction[size_t(bit)] < 0) mask |= uint16_t(1u << (8 + bit));
    ++kept;
  }
  return mask;
}

// A piece that touches its cell only at a corner cuts off that corner's sample, which lies on the curve: right
// while both crossings stayed at that corner, but when one of the edges kept another curve's crossing instead
// (merge_edge_crossings) the segment would cut a large part of the cell off, so it is dropped (the
// reconstruction keeps the sample out of both sides either way: formats/crease_reconstruction.h).
bool corner_piece_kept(const CreaseCellEdges& e, int bit) {
  const int m = kCreasePairFirst[bit];  // corner cut bit m joins edges m and m + 1 at corner C_{m+1}
  return e.along[m] >= 1.0 - 1.5 * double(kCreaseMinT) && e.along[(m + 1) % 4] <= 1.5 * double(kCreaseMinT);
}

// The junctions that stay: per cell the candidate with the most spokes (ties: the first), its point moved towards
// the centroid of the cell's edge points until it lies kCreaseMinT inside their quadrilateral (a point the
// merged crossings left outside it); a candidate whose centroid is not that far inside is dropped, its cell keeping
// the pairs of join_curve_ends. Sorted by cell.
std::vector<Junction> place_junctions(std::vector<Junction> candidates, const CreaseField& field) {
  std::stable_sort(candidates.begin(), candidates.end(), [](const Junction& a, const Junction& b) {
    return a.cell != b.cell ? a.cell < b.cell : std::popcount(a.spokes & 0x0fu) > std::popcount(b.spokes & 0x0fu);
  });
  std::vector<Junction> placed;
  for (const Junction& j : candidates) {
    if (!placed.empty() && placed.back().cell == j.cell) continue;
    const CreaseCellEdges e =
        crease_cell_edges(field, uint32_t(j.cell % field.cells_x()), uint32_t(j.cell / field.cells_x()));
    const double margin = double(kCreaseMinT);
    const double cu = 0.25 * (e.px[0] + e.px[1] + e.px[2] + e.px[3]),
                 cv = 0.25 * (e.py[0] + e.py[1] + e.py[2] + e.py[3]);
    if (!crease_point_inside_edge_points(e, cu, cv, margin)) continue;
    // The inside is convex: along the way from the point to the centroid it is one interval ending at the centroid;
    // the point moves by the smallest fraction of that way that reaches it (bisection).
    double move = 0.0;
    if (!crease_point_inside_edge_points(e, j.u, j.v, margin)) {
      double lo = 0.0;
      move = 1.0;
      for (int step = 0; step < 60; ++step) {
        const double mid = 0.5 * (lo + move);
        (crease_point_inside_edge_points(e, j.u + mid * (cu - j.u), j.v + mid * (cv - j.v), margin) ? move : lo) = mid;
      }
    }
    placed.push_back({j.cell, j.u + move * (cu - j.u), j.v + move * (cv - j.v), j.spokes});
  }
  return placed;
}

// A junction cell's spokes: the junction's, and both edges of every other piece through the cell (bent through the
// junction: a piece from the pair's first edge to its second runs in by the first and out by the second).
uint8_t junction_spokes(uint8_t spokes, const CellPieces& cell) {
  for (int bit = 0; bit < 6; ++bit) {
    if (!cell.count[size_t(bit)]) continue;
    const int in = cell.direction[size_t(bit)] >= 0 ? kCreasePairFirst[bit] : kCreasePairSecond[bit];
    const int out = in == kCreasePairFirst[bit] ? kCreasePairSecond[bit] : kCreasePairFirst[bit];
    if (!((spokes >> in) & 1u)) spokes |= uint8_t((1u << in) | (1u << (4 + in)));
    if (!((spokes >> out) & 1u)) spokes |= uint8_t(1u << out);
  }
  return spokes;
}

// Every cell's signature from its pieces, rows in parallel; each row counts its own, summed in row order. The
// junction records of the cells that are junctions, in cell order.
void assign_cell_signatures(const GroupedByKey<CellPiece>& by_cell, const std::vector<Junction>& junctions,
                            CreaseField& field, SimplifyStatistics& stats) {
  std::vector<uint64_t> row_deleted(field.cells_y(), 0), row_with_segments(field.cells_y(), 0);
  std::vector<std::vector<Junction>> row_junctions(field.cells_y());
  parallel_for(0, field.cells_y(), [&](int64_t j) {
    auto junction = std::lower_bound(junctions.begin(), junctions.end(), field.cell_index(0, uint32_t(j)),
                                     [](const Junction& a, size_t cell) { return a.cell < cell; });
    for (uint32_t i = 0; i < field.cells_x(); ++i) {
      const size_t c = field.cell_index(i, uint32_t(j));
      field.segments[c] = 0;
      const bool is_junction = junction != junctions.end() && junction->cell == c;
      if (by_cell.begin(c) == by_cell.end(c) && !is_junction) continue;  // most cells: no curve passes
      CellPieces cell;
      for (size_t r = by_cell.begin(c); r < by_cell.end(c); ++r) {
        const CellPiece& piece = by_cell.records[r];
        if (piece.at_corner &&
            (is_junction || !corner_piece_kept(crease_cell_edges(field, i, uint32_t(j)), piece.bit))) {
          ++row_deleted[size_t(j)];
          continue;
        }
        ++cell.count[size_t(piece.bit)];
        cell.direction[size_t(piece.bit)] += piece.direction;
      }
      if (is_junction) {
        Junction placed = *junction++;
        placed.spokes = junction_spokes(placed.spokes, cell);
        row_junctions[size_t(j)].push_back(placed);
        field.segments[c] = kCreaseJunctionBit;
      } else {
        field.segments[c] = cell_signature(cell, row_deleted[size_t(j)]);
      }
      row_with_segments[size_t(j)] += field.segments[c] != 0;
    }
  });
  for (size_t j = 0; j < row_deleted.size(); ++j) {
    stats.deleted_segments += row_deleted[j];
    stats.cells_with_segments += row_with_segments[j];
    for (const Junction& junction : row_junctions[j]) {
      field.junction_cells.push_back(uint32_t(junction.cell));
      field.junction_points.push_back(float(junction.u));
      field.junction_points.push_back(float(junction.v));
      field.junction_spokes.push_back(junction.spokes);
    }
  }
  stats.junction_cells = field.junction_cells.size();
}

}  // namespace

SimplifyStatistics simplify_curves(const CurveSet& curves, CreaseField& field) {
  // The curves walked in parallel chunks of kCurvesPerChunk.
  constexpr size_t kCurvesPerChunk = 64;
  const size_t chunks = (curves.curves.size() + kCurvesPerChunk - 1) / kCurvesPerChunk;
  std::vector<CurveWalk> chunk_walks(chunks, CurveWalk(field));
  std::vector<SimplifyStatistics> chunk_stats(chunks);
  parallel_for(0, int64_t(chunks), [&](int64_t c) {
    for (size_t k = size_t(c) * kCurvesPerChunk; k < std::min(curves.curves.size(), size_t(c + 1) * kCurvesPerChunk);
         ++k)
      chunk_walks[size_t(c)].walk_curve(curves.curves[k], chunk_stats[size_t(c)]);
  });
  // Their lists in curve order (as one walk over all of them would record), the junctions' pieces last.
  SimplifyStatistics stats;
  std::vector<std::vector<EdgeCrossing>> h, v;
  std::vector<std::vector<CellPiece>> pieces;
  CurveWalk junctions(field);
  for (size_t c = 0; c < chunks; ++c) {
    h.push_back(std::move(chunk_walks[c].h));
    v.push_back(std::move(chunk_walks[c].v));
    pieces.push_back(std::move(chunk_walks[c].pieces));
    for (const auto& [point, at] : chunk_walks[c].ends) {
      std::vector<CurveEnd>& all = junctions.ends[point];
      all.insert(all.end(), at.begin(), at.end());
    }
    stats.input_segments += chunk_stats[c].input_segments;
    stats.input_crossings += chunk_stats[c].input_crossings;
  }
  chunk_walks.clear();
  junctions.join_curve_ends();
  pieces.push_back(std::move(junctions.pieces));
  // The three lists grouped by edge and by cell, one after the other, each freed once used: the walk's records
  // are the bake's largest transient memory (one 1024^2 map with 10^4 random segments: ~35 MB of records next to the
  // 37 MB field), so only one list is grouped at a time.
  const auto edge_of = [](const EdgeCrossing& c) { return c.edge; };
  merge_edge_crossings(group_by_key(std::move(h), field.crossing_h.size(), edge_of), field.crossing_h, stats);
  merge_edge_crossings(group_by_key(std::move(v), field.crossing_v.size(), edge_of), field.crossing_v, stats);
  field.junction_cells.clear();
  field.junction_points.clear();
  field.junction_spokes.clear();
  assign_cell_signatures(
      group_by_key(std::move(pieces), field.segments.size(), [](const CellPiece& p) { return size_t(p.cell); }),
      place_junctions(std::move(junctions.junctions), field), field, stats);
  return stats;
}

std::vector<CurveSegment> network_segments(const CreaseField& field) {
  // Rows in parallel, each into its own list, joined in row order (the same list whatever the thread count).
  std::vector<std::vector<CurveSegment>> rows(field.cells_y());
  parallel_for(0, field.cells_y(), [&](int64_t j) {
    for (uint32_t i = 0; i < field.cells_x(); ++i) {
      if (!(field.segments[field.cell_index(i, uint32_t(j))] & (kCreaseSegmentBits | kCreaseJunctionBit))) continue;
      const CreaseCellEdges c = crease_cell_edges(field, i, uint32_t(j));
      const Vec2 origin(double(i) - 0.5, double(j) - 0.5);
      if (c.junction) {  // spokes from the junction, each in its curve's direction
        const Vec2 e = origin + Vec2(c.ex, c.ey);
        for (int k = 0; k < 4; ++k) {
          if (!((c.spokes >> k) & 1u)) continue;
          const Vec2 pk = origin + Vec2(c.px[k], c.py[k]);
          rows[size_t(j)].push_back((c.spokes >> (4 + k)) & 1u ? CurveSegment{pk, e} : CurveSegment{e, pk});
        }
        continue;
      }
      for (int bit = 0; bit < 6; ++bit) {
        if (!(c.mask & (1u << bit))) continue;
        const int a = kCreasePairFirst[bit], b = kCreasePairSecond[bit];
        Vec2 pa = origin + Vec2(c.px[a], c.py[a]), pb = origin + Vec2(c.px[b], c.py[b]);
        if (c.mask & (1u << (8 + bit))) std::swap(pa, pb);
        rows[size_t(j)].push_back({pa, pb});
      }
    }
  });
  size_t total = 0;
  for (const auto& row : rows) total += row.size();
  std::vector<CurveSegment> out;
  out.reserve(total);
  for (const auto& row : rows) out.insert(out.end(), row.begin(), row.end());
  return out;
}

}  // namespace mbk
