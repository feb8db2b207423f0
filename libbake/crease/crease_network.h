// [Parilov05] Sec. 4.1, simplifying discontinuity curves to the allowed per-cell configurations:
//   - a cell edge is crossed at no more than one point (several crossings merged at their centre of mass);
//   - no more than two segments inside a cell (further ones deleted: those crossing the cell the fewest
//     times, ties by segment bit order);
//   - every segment ends on the cell boundary (a curve's part inside the cell where it starts or ends is
//     dropped: only its crossing point is kept, as in the paper). A polyline vertex inside a cell is not an
//     end: the cell gets the segment from the edge the polyline entered by to the edge it left by (the
//     paper's per-segment conversion would leave that cell without a segment, letting interpolation cross
//     the curve at every polyline corner; test: CreaseNetwork.PolylineCornerInsideCellKeepsASegment).
// The result is the discontinuity signature of formats/crease_field.h (crossings + per-cell segment masks).
//
// Method (ours; the paper uses a table of per-texel transformations): each input segment is walked through the
// cells it passes, in the order of its crossings with the lattice lines. Degenerate inputs are resolved by a
// symbolic perturbation of the curves by (+eps, +eps^2): a point on a vertical lattice line belongs to the cell
// on its right, on a horizontal line to the cell below; a segment lying on a lattice line runs inside the
// cells right of (below) it, crossing the perpendicular edges at t = 0 (clamped to kCreaseMinT); a segment
// through a lattice vertex crosses the vertical line first when it runs right (dx > 0), else the horizontal.
// Every crossing is clamped to [kCreaseMinT, 1 - kCreaseMinT] of its edge. A curve through a sample crosses the two
// edges beside it at their ends; such a crossing yields to any other crossing of the same edge (it is not merged
// with it), and the piece between them, which touches its cell only at that corner, is kept only while both of its
// crossings stayed at the corner (test: CreaseNetwork.CrossingAtASampleYieldsToAnotherCurvesCrossing).
#pragma once

#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/crease_field.h"
#include "libbake/crease/curve_set.h"

namespace mbk {

struct SimplifyStatistics {
  uint64_t input_segments = 0;
  uint64_t input_crossings = 0;      // crossings of input segments with cell edges
  uint64_t crossed_edges = 0;        // edges with a crossing after merging
  uint64_t merged_edges = 0;         // edges where several crossings were merged
  double max_merge_shift = 0.0;      // texels: the farthest an input crossing moved when merged
  uint64_t cells_with_segments = 0;  // cells holding one or two segments
  uint64_t deleted_segments = 0;     // cell segments removed by the two-per-cell rule
  uint64_t junction_cells = 0;       // cells whose creases meet at a junction point (spokes)
  nlohmann::json to_json() const;
};

// Fills field.crossing_h, crossing_v and segments (field allocated for the map's size). Deterministic.
SimplifyStatistics simplify_curves(const CurveSet& curves, CreaseField& field);

// The simplified network as directed segments in texel coordinates, cell by cell in row-major order (a
// segment joining opposite edges passes through the cell's centre point E and is returned whole).
std::vector<CurveSegment> network_segments(const CreaseField& field);

}  // namespace mbk
