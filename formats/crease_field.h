// The data of the `crease` asset kind (formats/SPEC.md, "Kind 6: crease"), shared by the bake, the validator
// and the reconstruction: [Parilov05]'s discontinuity map, distance map and gradient map on one lattice.
//
// Lattice. For a W x H normal map (texel coordinates x right, y = row down, map [0, W] x [0, H]), samples sit
// at the texel centres extended by one ring: sample (i, j), 0 <= i <= W + 1, 0 <= j <= H + 1, at
// (i - 0.5, j - 0.5). Its normal is the map's texel (i - 1, j - 1) clamped to the map (clamp-to-edge), its
// distance and gradient are exact at its own position. The reconstruction cells are the squares between
// four samples ([Parilov05] Sec. 4.3: "only samples at the corners of the texel"): cell (i, j), 0 <= i <= W,
// 0 <= j <= H, spans [i - 0.5, i + 0.5] x [j - 0.5, j + 0.5] with corners C0 = sample (i, j) (top left),
// C1 = (i + 1, j), C2 = (i + 1, j + 1), C3 = (i, j + 1). Cell (i, j) holds point (x, y) when
// i = floor(x + 0.5), j = floor(y + 0.5) (clamped to the cell range).
//
// Discontinuity signature (an encoding equivalent to the paper's four boundary distances plus edge indices,
// Sec. 5): one crossing per lattice edge, shared by the two cells it bounds, and a per-cell segment mask.
// - crossing_h[j][i] (j <= H + 1, i <= W): the edge from sample (i, j) to (i + 1, j); crossing_v[j][i]
//   (j <= H, i <= W + 1): the edge from sample (i, j) to (i, j + 1). Each holds t in [kCreaseMinT,
//   1 - kCreaseMinT], the crossing at sample + t along +x (or +y), or kCreaseNoCrossing.
// - A cell's edges: e0 top = crossing_h[j][i], e1 right = crossing_v[j][i + 1], e2 bottom = crossing_h[j + 1][i],
//   e3 left = crossing_v[j][i]. The edge point P_k is the crossing, or the edge's midpoint when it has none.
// - segments[j][i], u16: bit m (m = 0..3) is the segment P_m - P_{m+1 mod 4} (cutting off corner C_{m+1}),
//   bit 4 is P0 - P2, bit 5 is P1 - P3. Bit 8 + b says the segment of bit b runs from its second point to its
//   first (the direction of the input curve, which sets the sides of one-sided profiles). At most two
//   segment bits, each joining two edges that have a crossing; no other bits. Or, alone, bit 6: a junction cell.
// - Junctions (where three or more facets meet, or two curves meet at an angle, inside a cell): the cell's centre
//   E is the curves' meeting point, stored in the junction records, and its segments are spokes E - P_k.
//   junction_cells[n] (u32, strictly increasing) is the cell index j (W + 1) + i, junction_points[n] = (u, v)
//   E in cell-local coordinates (u right, v down; strictly inside the quadrilateral P0 P1 P2 P3), and
//   junction_spokes[n] (u8) bit k the spoke E - P_k (k = 0..3; at least two, each on a crossed edge), bit 4 + k
//   that it runs from P_k to E (else from E to P_k). A file without the three sections has no junction.
//
// Distance map: distance[j][i], unsigned distance (texels) from sample (i, j) to the nearest segment of the
// simplified network. Gradient map: gradient[j][i] = (gx, gy), a unit vector, the gradient of the distance
// (pointing away from the nearest point: the normal of a profile p(d) is (-p'(d) g, 1)) after constrained
// Laplacian smoothing. Side map: side[j][i] = +1 when cross(b - a, x - a) >= 0 for the sample x and its nearest
// directed segment a -> b, i.e. the sample lies to the right of the direction of travel as seen on screen
// (y down); else -1.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace mbk {

class Asset;
class AssetWriter;

inline constexpr uint32_t kCreaseKindId = 6;
inline constexpr float kCreaseNoCrossing = -1.0f;
// Crossings are kept this far (in cell widths) from the lattice samples, so that an edge point never
// coincides with a corner and every one of the 8 triangles of a cell keeps a positive area.
inline constexpr float kCreaseMinT = 1.0f / 1024.0f;
// A sample nearer a segment than this (texels) lies on the crease: the crossings beside it were only nudged off it
// by kCreaseMinT, and its normal may belong to either side (formats/crease_reconstruction.h).
inline constexpr double kCreaseOnCurveDistance = 2.0 * kCreaseMinT;
inline constexpr uint32_t kCreaseMaxSegmentsPerCell = 2;
inline constexpr uint16_t kCreaseSegmentBits = 0x3f;
inline constexpr uint16_t kCreaseReversedBits = 0x3f00;
inline constexpr uint16_t kCreaseJunctionBit = 0x40;

// The edges (0..3) that segment bit b (0..5) joins.
inline constexpr int kCreasePairFirst[6] = {0, 1, 2, 3, 0, 1};
inline constexpr int kCreasePairSecond[6] = {1, 2, 3, 0, 2, 3};
// The segment bit joining edges a and b (a != b), in either order.
int crease_pair_bit(int a, int b);

struct CreaseField {
  uint32_t width = 0, height = 0;        // the normal map
  std::vector<float> normals;            // [H][W][3], the map's unit normals (+Y, tangent space)
  std::vector<float> distance;           // [H + 2][W + 2]
  std::vector<float> gradient;           // [H + 2][W + 2][2]
  std::vector<int8_t> side;              // [H + 2][W + 2]
  std::vector<float> crossing_h;         // [H + 2][W + 1]
  std::vector<float> crossing_v;         // [H + 1][W + 2]
  std::vector<uint16_t> segments;        // [H + 1][W + 1]
  std::vector<uint32_t> junction_cells;  // [N], cell indices, increasing
  std::vector<float> junction_points;    // [N][2], E in cell-local coordinates
  std::vector<uint8_t> junction_spokes;  // [N], spokes and their directions

  uint32_t samples_x() const { return width + 2; }
  uint32_t samples_y() const { return height + 2; }
  uint32_t cells_x() const { return width + 1; }
  uint32_t cells_y() const { return height + 1; }
  size_t sample_index(uint32_t i, uint32_t j) const { return size_t(j) * samples_x() + i; }
  size_t cell_index(uint32_t i, uint32_t j) const { return size_t(j) * cells_x() + i; }
  size_t h_edge_index(uint32_t i, uint32_t j) const { return size_t(j) * cells_x() + i; }
  size_t v_edge_index(uint32_t i, uint32_t j) const { return size_t(j) * samples_x() + i; }
  // The map normal at sample (i, j): texel (i - 1, j - 1) clamped to the map.
  const float* sample_normal(uint32_t i, uint32_t j) const {
    const uint32_t x = std::clamp<int64_t>(int64_t(i) - 1, 0, width - 1);
    const uint32_t y = std::clamp<int64_t>(int64_t(j) - 1, 0, height - 1);
    return &normals[(size_t(y) * width + x) * 3];
  }
  // Sizes all arrays for width x height: crossings none, no junction, side +1, everything else zero.
  void allocate(uint32_t w, uint32_t h);
  // The same for the normals, crossings and segments only (the distance maps stay empty until made).
  void allocate_lattice(uint32_t w, uint32_t h);
  // The junction record of a cell (by cell index), or -1.
  int64_t junction_index(size_t cell) const;
};

// One cell's edge points in cell-local coordinates (u right, v down, [0, 1]^2; corner C0 at (0, 0)).
struct CreaseCellEdges {
  double px[4], py[4];  // P_k
  double along[4];      // P_k's fraction along the edge from C_k to C_{k+1}
  bool crossing[4];     // the edge has a crossing
  uint16_t mask;        // the cell's segment word
  // The spokes E - P_k (bit k): a junction's record, with its directions (bit 4 + k: from P_k to E), or the spokes of
  // the diagonals (P0 - P2 is spokes 0 and 2, P1 - P3 spokes 1 and 3; their directions are in the mask), 0 without.
  uint8_t spokes;
  bool junction;  // the word is a junction and its record was found: E = (ex, ey)
  double ex, ey;  // E: the junction, or the intersection of P0P2 and P1P3
};
CreaseCellEdges crease_cell_edges(const CreaseField& field, uint32_t i, uint32_t j);

// Whether (u, v) lies inside the quadrilateral P0 P1 P2 P3 of a cell's edge points, at least `margin` (cell widths)
// from each of its sides. The quadrilateral is convex (one point on each side of the square).
bool crease_point_inside_edge_points(const CreaseCellEdges& edges, double u, double v, double margin);

// Section names.
inline constexpr const char* kCreaseNormalsSection = "normals";
inline constexpr const char* kCreaseDistanceSection = "distance";
inline constexpr const char* kCreaseGradientSection = "gradient";
inline constexpr const char* kCreaseSideSection = "side";
inline constexpr const char* kCreaseCrossingHSection = "crossing_h";
inline constexpr const char* kCreaseCrossingVSection = "crossing_v";
inline constexpr const char* kCreaseSegmentsSection = "segments";
inline constexpr const char* kCreaseJunctionCellsSection = "junction_cells";
inline constexpr const char* kCreaseJunctionPointsSection = "junction_points";
inline constexpr const char* kCreaseJunctionSpokesSection = "junction_spokes";

// Adds the ten sections, with the shapes above, to an asset being written; the field's arrays move into the writer
// (no copy of the file's bytes).
void add_crease_sections(AssetWriter& writer, CreaseField&& field);

// Reads parameters.width/height; empty when they are integers in 1..16384, else what is wrong.
std::string parse_crease_size(const Asset& asset, uint32_t& width, uint32_t& height);
// Empty when every section has the type and shape above for width x height (the three junction sections: all or
// none, with one N), else what differs.
std::string check_crease_section_shapes(const Asset& asset, uint32_t width, uint32_t height);
// Reads a crease asset (parameters and shapes checked; Error(invalid_input) otherwise). Values are not
// checked: run the kind's invariants (validate) for that.
CreaseField read_crease_field(const Asset& asset);

}  // namespace mbk
