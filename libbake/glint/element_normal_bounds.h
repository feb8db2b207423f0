// The leaf intervals of the RMQ table: the box of normal components that one example texel's
// position-normal element reaches, not only its centre normal (libbake/glint/glint_technique.h).
//
// Texel i's element ([Yan16], [Wang20] Sec. 3.1) is evaluated as K x K sub-elements (K =
// kGlintSubElementsPerAxis, glint_technique.h): sub-element q sits at the texel's point u_q = u_i + (a + 1/2) / K
// - 1/2 per axis, inside one bilinear cell of the example (example_bilinear.h), and is the bilinear field
// linearized there, n_q + J_q (u - u_q), over its cut-off |u - u_q| <= 3 sigma_h / K per axis. With D_c^x the
// largest |difference| of component c between horizontally adjacent texels of the 3 x 3 block around i
// (texels outside the example skipped: the reader clamps, so those differences are 0) and D_c^y likewise
// vertically, the bilinear field gives |n_q,c - n_i,c| <= |u_q - u_i|_x D_c^x + |u_q - u_i|_y D_c^y and
// |J_q,c0| <= D_c^x, |J_q,c1| <= D_c^y, so every sub-element stays inside
//
//   n_c +/- (D_c^x + D_c^y) * (1 / 2 - 1 / (2 K) + 3 sigma_h / K)        (0.8995 (D^x + D^y) for K = 2)
//
// the leaf interval. This also bounds each sub-element over the disc of that radius, so the interval is
// conservative whichever cut-off shape a renderer uses. The intrinsic roughness sigma_r is applied at query
// time and is not in the interval. No clamping to [-1, 1]: linear elements leave the unit disc near the
// horizon, and the P-NDF evaluates them. The leaf does not bound the part of a blended element that comes from
// the blend weights' gradient (blended_range.h).
// Deviation [Wang20]: Algorithm 1's leaf is the texel's normal itself, so a range query could prune texels
// whose elements still reach the half vector (test: ElementNormalBounds.ContainsEverySubElement).
#pragma once

#include <cstdint>

#include "formats/rmq_query.h"
#include "libbake/image/normal_map.h"

namespace mbk {

// The half-widths of the interval for n_x and n_y: (D^x + D^y) * (1/2 - 1/(2K) + 3 sigma_h / K) (above).
Vec2 element_normal_reach(const NormalMap& example, uint32_t x, uint32_t row);
// element_normal_reach for every texel of one row, bit for bit, into reach_x[x] and reach_y[x] (width
// entries each): each difference between adjacent texels of rows row - 1 .. row + 1 is taken once, then
// maximised over the 3 x 3 blocks, instead of per texel (the RMQ bake's inner loop).
void element_normal_reach_row(const NormalMap& example, uint32_t row, double* reach_x, double* reach_y);
// The interval of n_x and n_y (the same bounds type as an RMQ query's answer) from the texel's normal and reach.
RmqBounds element_normal_bounds(const Vec3f& normal, const Vec2& reach);
RmqBounds element_normal_bounds(const NormalMap& example, uint32_t x, uint32_t row);

}  // namespace mbk
