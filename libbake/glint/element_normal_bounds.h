// The leaf intervals of the RMQ table: the box of normal components that one example texel's
// position-normal element reaches, not only its centre normal (libbake/glint/glint_technique.h).
//
// Texel i's element ([Yan16], [Wang20] Sec. 3.1) is n(u) = n_i + J_i (u - u_i) over the spatial cut-off
// |u - u_i| <= 3 sigma_h per axis (sigma_h = 1.5 / sqrt(12) texels). Over that square, component c ranges
// exactly over
//
//   n_c +/- (|J_c0| + |J_c1|) * 3 sigma_h                      (J from example_jacobian.h)
//
// (the extreme of a linear function over a square is at a corner). This also bounds the element over the
// disc |u - u_i| <= 3 sigma_h, so the interval is conservative whichever cut-off shape a renderer uses.
// The intrinsic roughness sigma_r is applied at query time and is not in the interval. No clamping to
// [-1, 1]: the linear element leaves the unit disc near the horizon, and the P-NDF evaluates that element.
// Deviation [Wang20]: Algorithm 1's leaf is the texel's normal itself, so a range query could prune texels
// whose elements still reach the half vector (test: ElementNormalBounds.SpreadIsJacobianTimesCutoff).
#pragma once

#include <cstdint>

#include "formats/rmq_query.h"
#include "libbake/image/normal_map.h"

namespace mbk {

// The half-widths of the interval, (|J_x0| + |J_x1|, |J_y0| + |J_y1|) * 3 sigma_h.
Vec2 element_normal_reach(const NormalMap& example, uint32_t x, uint32_t row);
// The interval of n_x and n_y (the same bounds type as an RMQ query's answer) from the texel's normal and reach.
RmqBounds element_normal_bounds(const Vec3f& normal, const Vec2& reach);
RmqBounds element_normal_bounds(const NormalMap& example, uint32_t x, uint32_t row);

}  // namespace mbk
