// One position-normal element seen through a Gaussian pixel footprint ([Yan16] Sec. 4, [Wang20] Eqs. 1-3): the
// closed-form integral over positions that the P-NDF sums, the element's total mass, and a sample from it.
//
// Units: positions u in target texels (target_patch_grid.h), normals s in normal components (n_x, n_y).
// Footprint: G_P(u) = exp(-|u - c|^2 / (2 sigma_p^2)) (isotropic; truncated by the P-NDF, not here).
// Element i ([Yan16]; docs/ARCHITECTURE.md): centre u_i, normal n_i, Jacobian J_i (dn/du), spatial sigma_h,
//   G_i(u, s) = exp(-|u - u_i|^2 / (2 sigma_h^2)) exp(-|s - n_i - J_i (u - u_i)|^2 / (2 sigma_r^2)),
// sigma_r the intrinsic roughness (the P-NDF's elements: glint_pndf.h). With d = u_i - c, r = s - n_i and
// delta = u - u_i, the exponent is -(delta^T A delta - 2 b^T delta + e) / 2 with
//   A = (1/sigma_p^2 + 1/sigma_h^2) I + J^T J / sigma_r^2,   b = -d / sigma_p^2 + J^T r / sigma_r^2,
//   e = |d|^2 / sigma_p^2 + |r|^2 / sigma_r^2,
// so the integral over all u is
//   k_i(s) = integral G_P G_i du = 2 pi / sqrt(det A) * exp(-(e - b^T A^-1 b) / 2)                      (1)
// and its integral over s (the element's mass in the footprint) is
//   m_i = 2 pi sigma_r^2 * 2 pi sigma_e^2 * exp(-|d|^2 / (2 (sigma_p^2 + sigma_h^2))),
//   sigma_e^2 = sigma_p^2 sigma_h^2 / (sigma_p^2 + sigma_h^2).                                           (2)
// Sampling s with density k_i / m_i: u ~ N(mean (sigma_h^2 c + sigma_p^2 u_i) / (sigma_p^2 + sigma_h^2),
// sigma_e^2 I) (the product G_P G_h), then s = n_i + J_i (u - u_i) + sigma_r N(0, I).
#pragma once

#include <array>

#include "libbake/core/eigen.h"

namespace mbk {

struct GlintFootprint {
  Vec2 center;         // c, target texels
  double sigma = 1.0;  // sigma_p, target texels (> 0)
  // How the pixel's half vector moves across the footprint: ds/du, normal units per target texel (finite). The
  // P-NDF at s is then the mean over the footprint of the NDF at s + slope (u - center) at each point u
  // (glint_pndf.h, "The half vector's slope field"); 0 for one half vector over the whole footprint.
  Mat2 slope = Mat2::Zero();
};

struct PositionNormalElement {
  Vec2 center;  // u_i
  Vec2 n;       // n_i
  Mat2 jacobian;
  double sigma_h = 0.0;  // spatial standard deviation, texels (> 0)
};

// Eq. (1) above.
double element_footprint_integral(const PositionNormalElement& element, const GlintFootprint& footprint, double sigma_r,
                                  const Vec2& s);
// Eq. (2) above; depends on the element only through its centre and sigma_h.
double element_footprint_mass(const Vec2& element_center, double sigma_h, const GlintFootprint& footprint,
                              double sigma_r);
// A normal with density k_i / m_i, from four independent uniform numbers in [0, 1).
Vec2 sample_element_normal(const PositionNormalElement& element, const GlintFootprint& footprint, double sigma_r,
                           const std::array<double, 4>& uniforms);

}  // namespace mbk
