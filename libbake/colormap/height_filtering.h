// Height-correlated colour filtering ([Heitz13] Sec. 5.1): a colour map applied to the heights h of a Gaussian
// microsurface, p_h = N(0, sigma_h^2), seen from w_o and lit from w_i, with Smith shadowing. Conventions: directions
// in the local frame of the mean surface (z out, unit length, z > 0); slopes s = -(n_x, n_y) / n_z with covariance
// Sigma (the slope distribution of a Gaussian surface is Gaussian and uncorrelated with its heights, [Heitz13]
// Sec. 3).
//
// - Smith Lambda for Gaussian slopes, Eq. (3): with mu = cot(theta) and sigma_s^2 the slope variance along w's
//   azimuth (phi^T Sigma phi, phi the unit azimuth),
//       Lambda = sigma_s / (sqrt(2 pi) mu) exp(-mu^2 / (2 sigma_s^2)) - erfc(mu / (sqrt(2) sigma_s)) / 2,
//   0 head-on (mu -> inf) and +inf at the horizon.
// - Visibility, Eq. (2): V(h, w) = P_h(h)^Lambda(w), P_h the height CDF. The averaged shadowing Eq. (13) is
//       V_bar = int P^(Lo + Li) p dh / int P^Lo p dh = (1 + Lo) / (1 + Lo + Li)
//   (u = P_h(h) is uniform on [0, 1] under p_h, so int P^L p dh = 1 / (1 + L)). (The paper's Eq. 13 omits p_h in
//   the denominator's integrand; its result is the one with p_h.)
// - The view- and light-dependent height distribution, Eq. (16): D_h(h) = (1 + L) P_h(h)^L p_h(h), L = Lo + Li,
//   whose mean mu_d and standard deviation sigma_d Eqs. (17, 18) approximate by
//       mu_d = alpha_mu sigma_h log(1 + beta_mu L),   sigma_d = sigma_h / (1 + alpha_sigma log(1 + beta_sigma L)).
//   Erratum: Eq. (18) writes sigma_d^2 as the raw second moment int h^2 D_h dh; the Gaussian N(mu_d, sigma_d^2)
//   that replaces D_h needs the central one, int (h - mu_d)^2 D_h dh. We use the central moment (the raw one
//   exceeds 1 for large L and is not what the form 1 / (1 + ...) <= 1 describes); tests/colormap/
//   height_filtering_test.cpp measures both against the paper's constants and refits them.
// - Filtered colour, Eq. (14): C_h_bar = V_bar <C, D_h> ~= V_bar [C * N(0, sigma_d^2)](mu_d): one lookup in the
//   prefiltered table (formats/colormap_layout.h). A noise r added to the heights shifts and widens it
//   (mu_d + mu_r, sigma_d^2 + sigma_r^2).
#pragma once

#include "libbake/core/eigen.h"

namespace mbk {

// Eq. (3) in terms of mu = cot(theta) >= 0 and sigma_s > 0: 0 for mu = +inf, +inf for mu = 0. Evaluated without
// overflow for every mu (the exp and erfc terms both vanish for mu / sigma_s > 38, giving exactly 0).
double smith_lambda_gaussian(double cot_theta, double sigma_s);
// Lambda of a direction (local frame, z > 0) over slopes with covariance Sigma: sigma_s^2 = phi^T Sigma phi.
// Head-on (w = +z) gives 0; z <= 0 gives +inf.
double smith_lambda(const Vec3& w, const Mat2& slope_covariance);

// Eq. (13).
double averaged_visibility(double lambda_o, double lambda_i);

// Mean and standard deviation of a height distribution, in units of sigma_h.
struct HeightMoments {
  double mean = 0.0, stddev = 1.0;
};

// Exact moments of D_h for L = Lo + Li >= 0 (Eqs. 16-18 with the central second moment), by Gauss-Legendre
// quadrature over z = h / sigma_h in [-40, 40] (2400 nodes; the integrand is smooth, so this is exact to ~1e-13).
// raw_second, when given, receives int z^2 D dz (the paper's Eq. 18 as printed).
HeightMoments height_moments_exact(double lambda_sum, double* raw_second = nullptr);

// The fitted forms of Eqs. (17, 18).
struct HeightFit {
  double alpha_mu = 0.39, beta_mu = 4.75, alpha_sigma = 0.26, beta_sigma = 1.13;  // the paper's constants
};
HeightMoments height_moments_fitted(double lambda_sum, const HeightFit& fit = {});

// Our refit of the same forms over L in [0, 20] (up to ~89 degrees for slope deviations up to 0.5; tests/colormap/
// height_filtering_test.cpp reproduces it): residuals 0.043 (mean) and 0.0032 (sigma) sigma_h at worst, against
// 0.131 and 0.028 for the paper's constants. The evaluator uses these.
inline constexpr HeightFit kRefitHeightConstants{0.5220, 1.9767, 0.3057, 0.9980};

// The filtering distribution of one footprint, in height units: C_h_bar ~= visibility * [C * N(0, stddev^2)](mean).
struct HeightFilter {
  double visibility = 1.0, mean = 0.0, stddev = 0.0;
};
HeightFilter height_filter(double sigma_h, double lambda_o, double lambda_i,
                           const HeightFit& fit = kRefitHeightConstants);

// Least-squares refit of the four constants against height_moments_exact at `samples` values of L spread
// geometrically over [lambda_min, lambda_max] plus L = 0 (Levenberg-Marquardt per pair, from the paper's
// constants). Residuals are in units of sigma_h.
struct HeightFitReport {
  HeightFit fit;
  double mean_max_residual = 0.0, mean_rms_residual = 0.0;
  double stddev_max_residual = 0.0, stddev_rms_residual = 0.0;
};
HeightFitReport height_fit_residuals(const HeightFit& fit, double lambda_min, double lambda_max, int samples);
HeightFitReport refit_height_moments(double lambda_min, double lambda_max, int samples);

}  // namespace mbk
