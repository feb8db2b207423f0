// [Parilov05] Sec. 4.3 and appendix A: the per-point reconstruction of a normal map with discontinuities from a
// `crease` asset (formats/crease_field.h), written to be ported to a shader: it reads only the four lattice
// samples at the corners of the point's cell and the cell's signature. It lives in formats/ because the
// evaluator (libbake/eval) may depend on formats only.
//
// 0. A cell that no discontinuity touches (no crossing on its edges) is interpolated bilinearly (Sec. 4.3).
// 1. Otherwise the cell is split into 8 triangles (Fig. 7): four corner triangles T_k = (P_{k-1}, C_k, P_k) and four
//    inner triangles I_k = (E, P_k, P_{k+1}), where P_k is edge k's crossing (or its midpoint) and E the
//    intersection of P0P2 and P1P3 - or, in a junction cell, the junction point stored for it. Every allowed
//    segment is an edge of this partition (P_m P_{m+1} separates T_{m+1} from I_m; P0P2 and P1P3 are pairs of
//    spokes through E; a junction's segments are spokes E P_k). (Deviation [Parilov05]: the paper keeps at most two
//    segments per cell, so where three facets meet inside a cell one of them is lost; a junction keeps up to four
//    creases meeting at their true point; test: CreaseReconstruction.JunctionCellsReproduceThreeFacetsExactly.)
// 2. Regions: the triangles connected through partition edges that are not segments. A point sees only the
//    values of its own region (side-aware interpolation, "never across a discontinuity").
// 3. Vertex values seen from region R (appendix step 3): a corner: its sample. An edge point P_k: distance 0 if
//    the edge has a crossing, else linear between the corners (Sec. 4.3); gradient and normal: linear between
//    the edge's corners whose corner triangles are in R (appendix 3.1.1), copied from the one that is
//    (3.1.2), or - when none is (the common end point of two segments, 3.1.3) - the mean of R's corners
//    (Deviation [Parilov05]: the paper copies "the opposite endpoint of either segment", itself copied from a
//    corner of R; the mean of R's corners is the same value when R reaches one corner and is defined for every
//    configuration; test: CreaseReconstruction.OppositeSidesStayInTheirHemisphere). The centre E: distance
//    0 when a segment passes through it, else the mean of the linear interpolants along P0P2 and P1P3 (the
//    paper's choice); gradient and normal likewise, or linear along a segment through E whose two ends R
//    touches, or (at a junction, too) the mean of R's edge points around E.
//    A corner sample that lies on a crease (distance < kCreaseOnCurveDistance) holds either side's normal or a
//    mix: when the region reaches corners off the curve, its normal is replaced by theirs - along an edge by the
//    edge's other corner, inside the cell by its two edge neighbours weighted by the point's distance from it
//    along each edge - so edges without a crossing stay continuous and planar facets are exact (Deviation
//    [Parilov05]: the paper assumes every sample lies strictly on one side; test:
//    CreaseReconstruction.SamplesOnACreaseSpeakForNeitherSide).
// 4. Barycentric interpolation in the point's triangle (Eq. 2 cases 1-3 are the three kinds of vertex
//    values above); the gradient and the normal are renormalised ("forced to be one").
// 5. Eq. (1) blends a profile p(d) with the map through b(d) (crease_normal below).
//
// Coordinates: texel coordinates of formats/crease_field.h (x right, y down). Points outside the map are
// clamped to the nearest cell.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/crease_field.h"

namespace mbk {

struct CreaseSample {
  double distance = 0.0;         // texels, >= 0, 0 on every segment
  double gradient[2] = {1, 0};   // unit, texel coordinates (y down)
  double normal[3] = {0, 0, 1};  // the map's normal interpolated on the point's side, unit, tangent space (y up)
  int side = 1;                  // the side map on the point's side: +1 or -1
  uint32_t cell_i = 0, cell_j = 0;
  int triangle = 0;  // 0..3 corner triangles T_k, 4..7 inner triangles I_k, -1 bilinear (no crossing in the cell)
};

CreaseSample reconstruct_crease(const CreaseField& field, double x, double y);

// Standard bilinear interpolation of the map's normals on the same lattice (ignores discontinuities):
// the baseline the reconstruction is compared with. Renormalised.
void bilinear_normal(const CreaseField& field, double x, double y, double out[3]);

// Crease profiles p(d), d in texels ([Parilov05] Sec. 3, Fig. 10): heights of the surface across the crease.
//   v:       p(d) = depth d / width               (a sharp V groove for depth > 0, a ridge for depth < 0)
//   rounded: p(d) = depth (d / width)^2           (a groove with a rounded bottom, slope 0 on the curve)
//   step:    one-sided: on side +1 p(d) = depth d / width, on side -1 p(d) = 0 (a bevel on one side only)
//   table:   heights table[k] at d = k width / (N - 1), linear between samples (N >= 2)
// Beyond d = width every profile is flat (p' = 0). width > 0.
enum class CreaseProfileKind { v, rounded, step, table };
struct CreaseProfile {
  CreaseProfileKind kind = CreaseProfileKind::v;
  double depth = 1.0;
  double width = 1.0;
  std::vector<double> table;
  // b(d) = 0 for d <= blend_start (w0), 1 for d >= blend_end (w), smoothstep between.
  double blend_start = 0.0, blend_end = 1.0;
  // p'(d) on the given side.
  double slope(double d, int side) const;
};
double crease_blend(const CreaseProfile& profile, double d);
// Names of the profile kinds ("v, rounded, step, table"); parsing one (false when unknown); the name of one.
std::string crease_profile_kind_names();
bool parse_crease_profile_kind(const std::string& name, CreaseProfileKind& kind);
const char* crease_profile_kind_name(CreaseProfileKind kind);

// [Parilov05] Eq. (1), renormalised, in tangent space:
//   n' = P0(-(1 - b) p'(d) g + b~ B_h) + ((1 - b) + b~ B_z) e_z,  b~ = b sqrt(p'(d)^2 |g|^2 + 1), |g| = 1,
// with g = (g_x, -g_y) turned from texel coordinates (y down) to tangent space (y up).
void crease_normal(const CreaseSample& sample, const CreaseProfile& profile, double out[3]);

}  // namespace mbk
