// Where a surface point and its pixel footprint land on the glint target plane ([Wang20] Sec. 3.1: the
// microstructure is mapped to surfaces through their uv parameterization), for the evaluator.
//
// THE V FLIP. The target plane's u_1 axis runs DOWN the example's rows (target_patch_grid.h, row 0 at the top),
// while tangent +v runs UP the image (libbake/image/normal_map.h). The mapping is the one plain normal mapping
// uses to read texels (libbake/image/normal_pyramid.h sample_bilinear: row coordinate (1 - v) H), unwrapped
// (the target plane is infinite, it does not tile):
//     u_0 = uv_u * W,     u_1 = (1 - uv_v) * H,
// so one uv unit spans the example's width and height once, as in plain normal mapping, and moving +v moves
// -u_1 (up the rows). Normal components need no flip: n_x is along tangent +u, n_y along +v in both (+Y
// convention). Derivatives with respect to uv: dn/duv = J * diag(W, -H) (tangent_jacobian()).
//
// Footprint: the pixel's uv derivatives (ray differentials, libbake/eval/uv_footprint.h) in target texels,
// isotropic: sigma_p = max(max(|du/dx|, |du/dy|) / sqrt(12), kGlintMinFootprintSigma) texels: the standard
// deviation of a one-pixel box along the footprint's longer axis (the variance of the box-filtered pixel the
// reference resolves with many rays), so the Gaussian truncated at 3 sigma_p spans 1.7 pixels; the floor keeps
// at least one texel centre in any footprint (magnification shows the blend of the nearest elements).
#pragma once

#include <cstdint>

#include "libbake/core/eigen.h"
#include "libbake/glint/position_normal_element.h"

namespace mbk {

inline constexpr double kGlintMinFootprintSigma = 0.5;  // texels

// The target point of uv (above), for a W x H example.
Vec2 glint_target_point(const Vec2& uv, uint32_t width, uint32_t height);
// dn/duv from the point query's J = dn/du (rows n_x, n_y; columns d/du, d/dv).
Mat2 glint_tangent_jacobian(const Mat2& target_jacobian, uint32_t width, uint32_t height);
// The footprint of a pixel at uv with uv derivatives duv_dx, duv_dy (above). Non-finite derivatives (grazing
// rays) give a non-finite sigma, which footprint_texels() refuses: the caller skips such pixels.
GlintFootprint glint_pixel_footprint(const Vec2& uv, const Vec2& duv_dx, const Vec2& duv_dy, uint32_t width,
                                     uint32_t height);

}  // namespace mbk
