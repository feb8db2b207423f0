// The range query of the blended microstructure ([Wang20] Sec. 4.3-4.5): conservative bounds of the blended
// normal components over a node of target texels, from the four example patches' RMQ ranges pushed through the
// monotone blend, and the exact bounds of one target texel's element (what the P-NDF's leaves test).
//
// Target texels. The P-NDF's Gaussian elements sit on the target plane's texel grid: target texel (t_0, t_1)
// (integers, any sign) has its centre at u = (t_0 + 0.5, t_1 + 0.5) (target_patch_grid.h coordinates: u_1 runs
// DOWN the example's rows). With an even patch side P the target patch side h = P / 2 is a whole number of
// texels, so texel t lies in target patch I = floor(t / h) at local index l = t - I h in [0, h), and corner a
// of that patch (a = I or I + 1) reads it at the CENTRE of example texel origin(a) + l + (I + 1 - a) h: every
// target texel is a blend of four example texels, never of points between them.
//
// A node is a rectangle of texels [l_0, l_0 + w) x [l_1, l_1 + h') inside one target patch. Its bounds are built
// from two ranges:
// - per corner k, the RMQ bounds of the example texels the node reads (formats/rmq_query.h: exact over the
//   stored leaf intervals, which are each texel's element reach, element_normal_bounds.h, quantized outward);
// - the local coordinates f = (l + 0.5) / h of the node's texel CENTRES, a box [f_lo, f_hi] in [0, 1)^2.
// The blend is monotone increasing in every corner value ([Wang20] Sec. 4.5), so a lower bound blends the
// corners' minima and an upper bound their maxima; the weights vary over the node and are bounded over the
// WHOLE box, not only at its corners:
// - linear:    L(f) = sum_k w_k(f) c_k is bilinear in f, so its extremes over the box are at the box's corners
//              (exact for the given c_k).
// - variance:  n = m + N(f) / W(f), N = sum_k w_k (c_k - m) (bilinear: corners), W = ||w||_2 =
//              sqrt(q(f_0) q(f_1)), q(t) = (1 - t)^2 + t^2, convex with its minimum 1/2 at t = 1/2: W_min over
//              the box takes each q at the point of its interval nearest 1/2 (INSIDE the patch, not a corner),
//              W_max at the interval end farther from 1/2. Lower bound m + N_min / (N_min >= 0 ? W_max : W_min),
//              upper bound m + N_max / (N_max >= 0 ? W_min : W_max): interval division, conservative.
// - histogram: c_k -> G(c_k) through the forward LUT (monotone), the variance bound with m = 0 in Gaussian
//              space, then G^-1 through the inverse LUT (monotone).
// - none:      the union of the ranges of the corners that are the nearest vertex somewhere in the box
//              (f_0 >= 1/2 selects the corner on the +u_0 side, as in blended_normal.h).
// Every bound is finally widened by kGlintRangeRoundingMargin, so that double rounding (one corner evaluation
// against another, the LUTs' piecewise-linear steps) can never put a texel's value an ulp outside its node.
//
// The element bounds of one texel are the same blend of the STORED leaf intervals of its four example texels
// (the table's level 0, as quantized) at its own weights (a degenerate box): the normal box its element
// reaches. The P-NDF truncates an element at that box widened by the normal cut-off, and since the node bounds
// contain every texel's element bounds (a square's stored minimum is the minimum of its leaves' stored minima:
// outward rounding is monotone; the weight box contains each centre), pruning a node never drops a
// contributing element: the traversal equals brute force (glint_pndf.h). Reading the leaves from the table,
// not recomputing them from the example, keeps element and node bounds one definition whatever microbake
// version baked the table.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "formats/rmq_query.h"
#include "libbake/core/eigen.h"
#include "libbake/glint/blended_normal.h"

namespace mbk {

inline constexpr double kGlintRangeRoundingMargin = 1e-12;  // normal units

// The pure blend of corner ranges over a box of local coordinates (rules above). `corner` in the order of
// TargetPatchLocation::corners; `mean` is the example's channel means (variance mode); `lut` is needed for
// histogram mode. Requires 0 <= f_lo <= f_hi <= 1 and min <= max in every corner range.
RmqBounds blend_range_bounds(GlintBlendMode mode, const Vec2& f_lo, const Vec2& f_hi,
                             const std::array<RmqBounds, 4>& corner, const Vec2& mean, const StandardizationLut* lut);

struct TargetNode {
  int64_t patch_i = 0, patch_j = 0;  // target patch
  uint32_t x0 = 0, y0 = 0;           // first local texel, in [0, h)
  uint32_t width = 1, height = 1;    // texels; x0 + width <= h, y0 + height <= h
};

class GlintRangeQuery {
 public:
  // References (does not copy) the point query and the table, which must outlive it. Throws
  // Error(invalid_input) when the patch side is odd or the table describes an example of another size.
  GlintRangeQuery(const GlintPointQuery& point, const RmqTableView& rmq);

  const GlintPointQuery& point() const { return *point_; }
  uint32_t target_side() const { return side_; }  // h, in texels

  // The example texel that corner k (0..3) of target patch (i, j) reads for local texel (x, y).
  std::array<uint32_t, 2> example_texel(int64_t patch_i, int64_t patch_j, int corner, uint32_t x, uint32_t y) const;

  // Conservative bounds of every element of the node (RMQ ranges, rules above). `lookups`, when given,
  // receives the number of stored squares read.
  RmqBounds node_bounds(const TargetNode& node, uint32_t* lookups = nullptr) const;
  // The element bounds of target texel (t_0, t_1) (rules above).
  RmqBounds element_bounds(int64_t t0, int64_t t1) const;

 private:
  // A corner's stored codes in blend space: dequantized, and for `histogram` through G - from a table of G of
  // every code's value, filled once (the same doubles as looking each up: 16 of the 20 LUT lookups of a node saved).
  RmqBounds corner_bounds(const RmqCodes& codes) const;
  RmqBounds blend(const Vec2& f_lo, const Vec2& f_hi, const std::array<RmqBounds, 4>& corner) const;
  const GlintPointQuery* point_;
  const RmqTableView* rmq_;
  uint32_t side_;
  std::array<std::vector<double>, 2> gaussian_of_code_;  // histogram only: G_T(value(code)) per channel
};

}  // namespace mbk
