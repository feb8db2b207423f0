// Slope-correlated colour filtering ([Heitz13] Sec. 5.2): a colour map driven by the microsurface slope, seen from
// w_o. Eq. (20) needs the view-dependent slope filtering distribution D_s; the paper says it is well approximated
// by a shifted and stretched Gaussian and leaves the derivation to a supplement we do not have. Ours, below, is
// the exact moment match (the Gaussian with D_s's mean and covariance), in closed form.
//
// Setting (local frame of the mean surface, z out, w_o unit with z > 0). Slopes s = (s_x, s_y) = -(n_x, n_y) / n_z
// over the footprint are Gaussian, N(s_bar, Sigma) ([Heitz13] Sec. 5.2: s_bar and Sigma from the footprint's
// statistics). The colour is C(d . s) for a unit direction d in the tangent plane (the slope along d: a 1-D
// driver, so the prefiltered table of formats/colormap_layout.h applies).
//
// Derivation. Eq. (19)'s C_s_bar averages over microsurface area dA with weight max(cos theta_o, 0). A microfacet
// with slope s above projected area dx has dA = sqrt(1 + |s|^2) dx and cos theta_o = n . w_o = (w_z - s . w_xy) /
// sqrt(1 + |s|^2), so the weight per unit projected area is
//     (w_z - s . w_xy)_+ = (a + t)_+,   a = w_z,  t = b . s,  b = -w_xy,
// and D_s(s) = p(s) (a + b . s)_+ / E[(a + b . s)_+]: the Gaussian tilted by a clamped linear ramp (it shifts
// toward facets facing w_o and stretches/squeezes along b; it is p itself head-on, b = 0).
// The weight depends on s only through t ~ N(m, v), m = b . s_bar, v = b^T Sigma b, and given t, s is Gaussian
// with mean s_bar + Sigma b (t - m) / v and covariance Sigma - Sigma b b^T Sigma / v. So
//     E_D[s]   = s_bar + Sigma b (E_w[t] - m) / v,
//     Cov_D[s] = Sigma + Sigma b b^T Sigma (Var_w[t] - v) / v^2,
// where E_w, Var_w are the moments of t under the density proportional to (a + t)_+ N(t; m, v). With u = a + t =
// sqrt(v) x, x ~ N(k, 1) restricted by the weight x_+, k = (a + m) / sqrt(v), and
//     T_n(k) = E[x^n 1{x > 0}] for x ~ N(k, 1):  T_1 = k Phi + phi,  T_2 = (k^2 + 1) Phi + k phi,
//                                                 T_3 = (k^3 + 3k) Phi + (k^2 + 2) phi   (Phi, phi at k),
// the weighted moments are E_w[x] = T_2 / T_1 and E_w[x^2] = T_3 / T_1, so E_w[t] = sqrt(v) T_2 / T_1 - a and
// Var_w[t] = v (T_3 / T_1 - (T_2 / T_1)^2). The projected area per unit footprint area is E[(a + t)_+] =
// sqrt(v) T_1.
// Numerics. For k < -10 (the mean facet faces away by more than 10 standard deviations) the closed forms cancel;
// there T_n = phi(k) I_n(-k) with I_n(c) = int_0^inf x^n exp(-c x - x^2 / 2) dx, summed from its asymptotic series
// sum_j (-1/2)^j (n + 2j)! / (j! c^(n + 2j + 1)) up to its smallest term (below e^-50 relative for c >= 10), so
// phi(k) cancels in the ratios. v = 0 (head-on, or no slope variance along b) leaves p unchanged.
// Tests: tests/colormap/slope_filtering_test.cpp compares the moments and the filtered colour with brute-force
// 2-D integration of p (a + b . s)_+ from head-on to 89.9 degrees, with tilted mean slopes and anisotropic Sigma.
#pragma once

#include "libbake/core/eigen.h"

namespace mbk {

struct SlopeGaussian {
  Vec2 mean = Vec2::Zero();
  Mat2 covariance = Mat2::Zero();
};

struct VisibleSlopes {
  SlopeGaussian gaussian;       // the moment-matched D_s
  double projected_area = 1.0;  // E[(w_z - s . w_xy)_+]: microsurface area facing w_o, projected, per footprint area
};

// D_s's moments for slopes N(s_bar, Sigma) seen from w_o (unit, z > 0). Error(runtime_failure) when w_o.z() <= 0.
VisibleSlopes visible_slope_distribution(const SlopeGaussian& slopes, const Vec3& wo);

// The 1-D driver d . s under a slope Gaussian: mean d . mean and standard deviation sqrt(d^T Sigma d).
struct DriverStatistics {
  double mean = 0.0, stddev = 0.0;
};
DriverStatistics slope_driver(const SlopeGaussian& slopes, const Vec2& direction);

}  // namespace mbk
