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
// - normal: element t counts at s only if s lies in its element bounds (blended_range.h: the blend of its four
//   example texels' leaf intervals, the reach of its sub-elements) widened by 4 sqrt(C_ii) in component i,
//   C the elements' normal covariance (sigma_r^2 I plus the footprint's sweep, below): the box holds C's
//   4-sigma ellipse;
// - position: the element's Gaussian is integrated over the whole plane (the 3 sigma_h spatial cut-off only
//   sizes the leaf intervals).
// Directional spread: [Wang20] and [Yan16] evaluate D_P at one s per pixel, as if the half vector were the same
// over the whole pixel. Under a point light or a perspective camera it sweeps s across the pixel (by ds/dx,
// ds/dy per pixel step); a renderer that shades a pixel once cuts that sweep into cells (pixel_sweep.h), averages
// D_P over their centres (evaluate_mean) and passes each cell's own sweep as footprint.sweep, the covariance S of
// s over the cell, and every element is evaluated with the normal covariance
// C = sigma_r^2 I + S in place of sigma_r^2 I: the elements' normal Gaussians convolved with the sweep, taken
// independent of position. C is anisotropic in general (at grazing angles s sweeps across the view many times
// faster than along it), so the elements are evaluated in whitened normals: with W = C^(-1/2) (symmetric),
// exp(-(s - n)^T C^-1 (s - n) / 2) = exp(-|W s - W n|^2 / 2), i.e. the element with W n, W J evaluated at W s
// with unit roughness (position_normal_element.h), and D_P picks up det W from the change of variables
// (the masses below are integrals over whitened normals). Deviation from the papers, measured: a flat map under
// two point lights at 96 x 54 rendered its highlights 29% too bright in one 8 x 8 block and 2% too dark in
// another against 16 x 16 rays per pixel without the sweep (test: GlintsEffect.FlatMapMatchesItsReference); an
// isotropic sweep (the mean of the two variances) streaked a grazing highlight toward the horizon (test:
// GlintsEffect.GrazingHighlightStaysWhereTheReferenceHasIt).
// Normalisation: D_P(s) = sum k(s) / sum m over the footprint's sub-elements, i.e. the untruncated D_P would
// integrate to exactly 1 over s; the normal truncation removes the mass beyond 4 sigma per component (< 1e-4).
//
// Traversal (Algorithm 3 with [Wang20] Sec. 5.2): the footprint's texel rectangle is split at target patch
// borders into one rectangle per covered patch, however many (never clamped in size); each is a root node.
// A node of more than one texel is pruned when s lies outside its range bounds (blended_range.h) widened by
// the normal cut-off, else split into (up to) four halves; a one-texel node is the element test above. Node bounds
// contain every element bound of the node, so pruning drops only elements that would add exactly 0.
// Deviation [Wang20]: Alg. 3 starts from a power-of-two square grown past the footprint; here nodes are the
// footprint's own rectangles halved, so no node reads texels outside the footprint (same result, fewer
// range queries).
//
// Aggregation (deviation [Wang20]: on maps that are mostly flat ground nearly every texel reaches the half
// vectors that make glints, so pruning alone visits every texel of the footprint): with `aggregate`, a node
// whose bounds are at most kGlintAggregateWidthSigmas (0.01) sigma_min wide in both components (sigma_min^2 the
// smaller eigenvalue of C), c their centre, is summed in closed form as if every element were N(s; c, C) times its
// mass (exact for elements with J = 0 and n = c: position_normal_element.h Eq. 1 reduces to m N(s; n, C)); the
// masses are separable, so a node costs two differences of running sums. Bound, in whitened normals (|W x| <=
// |x| / sigma_min): every element of such a node has its normals within the node's box up to its
// sub-elements' spatial cut-off (3 sigma_h / K: 0.54% of its mass beyond), i.e. within 0.0071 of c whitened, so
// where the whitened distance r = |W (s - c)| is at most 4.02, replacing N(s; n, C) by N(s; c, C) changes it by a
// factor within exp(+-(4.02 * 0.0071 + 0.0071^2 / 2)) = 1 +- 2.9%, and beyond that every element's Gaussian is
// below e^-8 of its peak, so its change is below 1e-5 of the peak; hence |D_agg - D| <= 0.03 D + 0.006 peak,
// peak = 1 / (2 pi sqrt(det C)) (test: GlintPndf.AggregatedTraversalWithinItsBound_1000Queries, isotropic and
// anisotropic sweeps).
// Sampling ([Wang20] Sec. 5.3): a sub-element is picked with probability m / sum m (m is separable in the two
// axes, so two 1-D inversions), a normal is drawn from k / m (in whitened normals, then mapped back by C^(1/2)), and
// the draw restarts when that normal lies outside its texel's truncation box: the samples' density is then exactly
// proportional to D_P.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "libbake/glint/blended_range.h"
#include "libbake/glint/position_normal_element.h"

namespace mbk {

struct TexelRange {
  int64_t t0_lo = 0, t0_hi = -1, t1_lo = 0, t1_hi = -1;  // inclusive; empty when lo > hi
  bool empty() const { return t0_lo > t0_hi || t1_lo > t1_hi; }
};

// The texels whose centres lie in the footprint's truncation square. Throws Error(invalid_input) for a
// non-finite centre, a sigma that is not finite and > 0, or a sweep that is not a finite covariance.
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
  // The mean of D_P over several normals in one traversal (a node is pruned when every normal is outside it;
  // the leaves share their sub-elements): what a renderer needs for the box sweep below. 0 for no normals.
  double evaluate_mean(const GlintFootprint& footprint, std::span<const Vec2> s, PndfStatistics* stats = nullptr,
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
  struct NormalKernel;  // the elements' normal covariance C and its whitening (glint_pndf.cpp)
  struct Normals;       // the normals of one evaluation, whitened, and their box (glint_pndf.cpp)
  NormalKernel normal_kernel(const GlintFootprint& footprint) const;
  // Element t's sum of k over its sub-elements and the normals, in whitened normals.
  double element_term(int64_t t0, int64_t t1, const GlintFootprint& footprint, const Normals& normals,
                      const NormalKernel& kernel) const;
  // Whether the box of normals lies outside the bounds b widened by the normal cut-off.
  static bool outside(const RmqBounds& b, const RmqBounds& normals, const NormalKernel& kernel);
  struct Query;  // what one traversal shares with every node (glint_pndf.cpp)
  double traverse(const TargetNode& node, const Query& q, PndfStatistics& stats) const;
  std::optional<Vec2> draw(const GlintFootprint& footprint, const TexelRange& t, const std::vector<double>& wx,
                           const std::vector<double>& wy, const std::function<double()>& uniform) const;

  const GlintRangeQuery* range_;
  double sigma_r_;
};

}  // namespace mbk
