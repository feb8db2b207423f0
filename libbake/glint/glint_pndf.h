// The P-NDF of the infinite blended microstructure over a Gaussian pixel footprint ([Wang20] Eqs. 1-3,
// Sec. 4.6, 5.2, 5.3, Algorithm 3): evaluation by the implicit-hierarchy traversal, the brute-force sum it must
// equal, and importance sampling.
//
// Elements: one per target texel t (blended_range.h), evaluated as K x K sub-elements (K =
// kGlintSubElementsPerAxis, glint_technique.h: why) of spatial sigma_h / K centred at u = t + (a + 1/2) / K,
// each with n and J from the point query there (blended_normal.h: inside a bilinear cell, never on a kink),
// integrated against the footprint in closed form (position_normal_element.h).
// Truncation (the SAME in every evaluation, so that traversal == brute force up to rounding):
// - footprint: the texels whose centres lie in the square |u_t - c|_inf <= 3 sigma_p (footprint_texels());
// - normal: element t counts at s only if s lies in its element box widened by 4 sigma_r per component: the
//   element bounds (blended_range.h: the blend of its four example texels' leaf intervals, the reach of its
//   sub-elements) shifted by -K (u - c) over its reach square (below; no shift when K = 0);
// - position: the element's Gaussian is integrated over the whole plane (the 3 sigma_h spatial cut-off only
//   sizes the leaf intervals and the reach square).
// The half vector's slope field (deviation [Wang20], [Yan16], which evaluate D_P at one s per pixel, as if every
// point of the footprint saw one half vector): under a point light or a perspective camera the half vector
// moves across the pixel, and a point u of the surface sees its OWN half vector. To first order its normal
// components at u are s(u) = s + K (u - c), K = footprint.slope = ds/du (glint_surface_mapping.h builds it as
// S M^-1 from the pixel's sweep S = ds/d(pixel) and uv Jacobian M = du/d(pixel)), and D_P at s is
// sum_i integral G_P(u) G_i(u, s(u)) du / sum_i m_i. Since
//   s(u) - n_i - J_i (u - u_i) = s - n'_i - J'_i (u - u_i),    n'_i = n_i - K (u_i - c),    J'_i = J_i - K,
// each element is Eq. (1) of position_normal_element.h with n', J', evaluated at s: exact for the linear field
// whatever K, and K = 0 is the point case. The masses m_i do not depend on n or J, so D_P still integrates to 1
// over s. The shifted box holds n'_i + J'_i (u - u_i) over every sub-element's cut-off: element t's
// sub-elements lie within kGlintElementReachTexels of its centre per axis (glint_technique.h), its element bounds
// hold n_i + J_i (u - u_i) there, and K (u - c) over that square is an interval per component.
// A renderer that shades a pixel once with a Gaussian footprint also cuts the pixel into sub-pixel cells, each its
// own footprint and half vector (pixel_sweep.h: a Gaussian is not the pixel's box).
// Measured against sub-pixel point NDFs through the same microstructure (test:
// GlintPndf.SlopeFieldFollowsTheMeanOfPointNdfsOverTheFootprint): relative L1 0.03-0.04 with the field, 0.33 with
// the sweep taken independent of position (every texel tested against every half vector of the pixel: the
// previous form, cells of the sweep box plus a residual covariance on the normals).
// Refinement under histogram blending (deviation [Wang20], [Yan16]): n = G^-1(z) per channel, and where a map
// is mostly one value G^-1 is nearly flat across that atom's Gaussian range and steep past it, a bend that a
// sub-element straddling it cannot follow linearized at its centre (a plateau-side centre puts all its mass at
// the flat value, a steep-side one spreads it far past the features). A sub-element over whose range of z G^-1
// bends away from its tangent (glint_technique.h: the rule; two inverse lookups per channel) is evaluated as
// R x R children of spatial sigma / R, each its own point query, weighted so that their masses sum to the
// sub-element's (the normaliser below does not change); sampling picks a child by mass.
// Measured (tests/glint/pndf_tail_mass_test.cpp): `gen scratches` kept 0.69-0.75 of the exact mass in
// [0.05, 0.2) without it, 0.96-1.04 with R = 4 (0.87-0.93 with R = 2); its price is one point query per child
// where the bends are (the query part of P-NDF evaluations on `gen scratches` about 3x slower; `gen bumps`, whose
// G^-1 has no bend, about 10%).
// Normalisation: D_P(s) = sum k(s) / sum m over the footprint's sub-elements, i.e. the untruncated D_P would
// integrate to exactly 1 over s; the normal truncation removes the mass beyond 4 sigma per component (< 1e-4).
//
// Traversal (Algorithm 3 with [Wang20] Sec. 5.2): the footprint's texel rectangle is split at target patch
// borders into one rectangle per covered patch, however many (never clamped in size); each is a root node.
// A node of more than one texel is pruned when s lies outside its range bounds (blended_range.h) shifted by
// -K (u - c) over the node's rectangle grown by the reach and widened by the normal cut-off, else split into
// (up to) four halves; a one-texel node is the element test above. Node boxes contain every element box of the
// node, so pruning drops only elements that would add exactly 0.
// Deviation [Wang20]: Alg. 3 starts from a power-of-two square grown past the footprint; here nodes are the
// footprint's own rectangles halved, so no node reads texels outside the footprint (same result, fewer
// range queries).
//
// Aggregation (deviation [Wang20]: on maps that are mostly flat ground nearly every texel reaches the half vectors
// that make glints, so pruning alone visits every texel of the footprint): with `aggregate`, a node (a single texel
// too, through its element box) whose shifted box (above, before widening) is at most kGlintAggregateWidthSigmas
// (0.01) sigma_r wide in both components, c_b its centre, is summed in closed form as if every element were N(s;
// c_b, sigma_r^2 I) times its mass (exact for elements with J' = 0 and n' = c_b: position_normal_element.h Eq. 1
// reduces to m N(s; n', .)); the masses are separable, so a node costs two differences of running sums. Bound: every
// element of such a node has its normals n'_i + J'_i (u - u_i) within the node's shifted box up to its sub-elements'
// spatial cut-off (3 sigma_h / K: 0.54% of its mass beyond), i.e. within 0.0071 sigma_r of c_b, so where r = |s -
// c_b| / sigma_r is at most 4.02, replacing the element by N(s; c_b, .) changes it by a factor within exp(+-(4.02 *
// 0.0071 + 0.0071^2 / 2)) = 1 +- 2.9%, and beyond that every element's Gaussian is below e^-8 of its peak, so its
// change is below 1e-5 of the peak; hence |D_agg - D| <= 0.03 D + 0.006 peak, peak = 1 / (2 pi sigma_r^2) (test:
// GlintPndf.AggregatedTraversalWithinItsBound_1000Queries, with and without slope fields).
// Sampling ([Wang20] Sec. 5.3): a sub-element is picked with probability m / sum m (m is separable in the two
// axes, so two 1-D inversions), a normal is drawn from k / m (with n', J'), and the draw restarts when that
// normal lies outside its texel's shifted truncation box: the samples' density is then exactly proportional to
// D_P.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "libbake/glint/blended_range.h"
#include "libbake/glint/position_normal_element.h"

namespace mbk {

struct TexelRange {
  int64_t t0_lo = 0, t0_hi = -1, t1_lo = 0, t1_hi = -1;  // inclusive; empty when lo > hi
  bool empty() const { return t0_lo > t0_hi || t1_lo > t1_hi; }
};

// The texels whose centres lie in the footprint's truncation square. Throws Error(invalid_input) for a
// non-finite centre, a sigma that is not finite and > 0, or a slope that is not finite.
TexelRange footprint_texels(const GlintFootprint& footprint);

// The reference the P-NDF approximates ([Wang20] Eq. 1 before Yan16's elements): the NDF of ONE point u of the
// infinite microstructure, the intrinsic-roughness Gaussian around its exact normal n(u) (the point query),
//   D_u(s) = exp(-|s - n(u)|^2 / (2 sigma_r^2)) / (2 pi sigma_r^2),
// untruncated, integrating to 1. Averaged over a pixel's area (a renderer's many rays per pixel) it converges
// to Eq. 1 with that pixel's footprint and the continuous normal field, which the P-NDF approximates with one
// linearized element per texel. Throws Error(invalid_input) unless sigma_r is finite and > 0.
double point_ndf(const GlintPointQuery& point, const Vec2& u, double sigma_r, const Vec2& s);

struct PndfStatistics {
  uint64_t nodes_visited = 0;  // range-query nodes plus element tests
  uint64_t elements_evaluated = 0;
  uint64_t rmq_lookups = 0;
  uint64_t nodes_aggregated = 0;
};

class GlintPndf {
 public:
  // References the range query (which must outlive it). Throws Error(invalid_input) unless sigma_r is finite
  // and > 0.
  GlintPndf(const GlintRangeQuery& range, double sigma_r);

  double sigma_r() const { return sigma_r_; }
  // D_P(s) by traversal; `stats`, when given, accumulates the work done. `aggregate` sums nearly constant
  // nodes in closed form (rules above: within the stated bound of brute force, not equal to it).
  double evaluate(const GlintFootprint& footprint, const Vec2& s, PndfStatistics* stats = nullptr,
                  bool aggregate = false) const;
  // D_P(s) summed over every texel of the footprint (the reference the traversal must equal).
  double evaluate_brute_force(const GlintFootprint& footprint, const Vec2& s) const;
  // A normal drawn with density D_P (rules above), from `uniform` (numbers in [0, 1)); nullopt when the
  // footprint holds no texel centre, or after 64 rejected draws in a row (never seen in the tests).
  std::optional<Vec2> sample(const GlintFootprint& footprint, const std::function<double()>& uniform) const;
  // One draw of the untruncated elements: a normal with density D_P when it lands inside its element's box,
  // else nullopt, so the fraction of draws that return a normal is D_P's integral (what truncation keeps).
  std::optional<Vec2> sample_once(const GlintFootprint& footprint, const std::function<double()>& uniform) const;

 private:
  // Element t's sum of k over its sub-elements at s, 0 when s is outside its shifted box (rules above).
  double element_term(int64_t t0, int64_t t1, const GlintFootprint& footprint, const Vec2& s) const;
  // Element t's shifted box, and its sum of k over its sub-elements at s whatever the box.
  RmqBounds element_box(int64_t t0, int64_t t1, const GlintFootprint& footprint) const;
  double sub_element_sum(int64_t t0, int64_t t1, const GlintFootprint& footprint, const Vec2& s) const;
  struct Query;  // what one traversal shares with every node (glint_pndf.cpp)
  double traverse(const TargetNode& node, const Query& q, PndfStatistics& stats) const;
  double aggregated_term(const RmqBounds& b, int64_t x, int64_t y, int64_t w, int64_t h, const Query& q) const;
  std::optional<Vec2> draw(const GlintFootprint& footprint, const TexelRange& t, const std::vector<double>& wx,
                           const std::vector<double>& wy, const std::function<double()>& uniform) const;

  const GlintRangeQuery* range_;
  double sigma_r_;
};

}  // namespace mbk
