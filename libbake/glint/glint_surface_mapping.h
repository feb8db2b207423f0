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
// Footprint: the evaluator covers a pixel's anisotropic footprint by probes along its major axis
// (libbake/eval/uv_footprint.h footprint_probes: N probes, each standing for a box of width w texels), and the
// P-NDF is the mean of the probes' P-NDFs, each over the isotropic Gaussian of sigma_p = max(w / sqrt(12),
// kGlintMinFootprintSigma) texels: the standard deviation of the box (the variance of the box-filtered pixel the
// reference resolves with many rays), so the Gaussian truncated at 3 sigma_p spans 1.7 w; the floor keeps at least
// one texel centre in any footprint (magnification shows the blend of the nearest elements). An elongated footprint
// of s1 x s2 texels thus costs N w^2 ~ s1 s2 texels, not the s1^2 of one circle over its longer axis, which also
// blurred the glints over many times the pixel's area at grazing angles.
// The half vector's slope field (glint_pndf.h): the renderer knows S = ds/d(pixel) (columns: the change of the half
// vector's normal components per pixel step x and y) and M = du/d(pixel) (the uv derivatives in target texels,
// diag(W, -H) [duv/dx duv/dy]: the v flip above), so to first order s moves across the surface by
//     K = ds/du = S M^-1 = S V diag(1 / sigma_1, 1 / sigma_2) U^T        (M = U diag(sigma_1, sigma_2) V^T).
// The P-NDF integrates over the probes' Gaussians, not over the pixel's image: where they reach further than the
// image (the 0.5-texel floor under magnification; a minor axis thinner than the probe's box width, sqrt(12)
// sigma_p), the field is spread over the footprint actually integrated, sigma_k replaced by
// max(sigma_k, sqrt(12) sigma_p), so that s still sweeps the pixel's own range S [-1/2, 1/2]^2 and no more.
// With the footprint equal to the pixel's image K is S M^-1 exactly; singular M (an edge-on pixel) stays finite
// through that floor; M = 0 or non-finite M or S (grazing rays) gives K = 0, one half vector per footprint.
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
// The footprint of one probe at uv standing for a box of `box_width` texels (above). A non-finite width (a grazing
// ray) gives a non-finite sigma, which footprint_texels() refuses: the caller skips such pixels.
GlintFootprint glint_probe_footprint(const Vec2& uv, double box_width, uint32_t width, uint32_t height);
// K = ds/du in target texels (above) from the half vector's steps S and the uv steps duv/dx, duv/dy of one pixel,
// for probes of sigma_p = probe_sigma texels.
Mat2 glint_half_vector_slope(const Mat2& steps, const Vec2& duv_dx, const Vec2& duv_dy, double probe_sigma,
                             uint32_t width, uint32_t height);

}  // namespace mbk
