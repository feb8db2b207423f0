// The von Mises-Fisher lobe on the unit sphere S^2 ([Han07] Sec. 7.6; Banerjee et al. 2005):
//     g(n; kappa, mu) = kappa / (4 pi sinh(kappa)) exp(kappa mu.n)                     [Han07] Eq. (7.15)
// and everything microbake computes from it: its mean resultant length A(kappa) = coth(kappa) - 1/kappa
// (Eq. 7.16), the inverse of A by a guarded Newton solve, the overflow-free log density, and its exact
// spherical-harmonic band factors.
//
// Never evaluated as written: sinh(kappa) and exp(kappa) overflow (kappa > ~710 in double). The density is
//     g = kappa / (2 pi (1 - exp(-2 kappa))) exp(kappa (mu.n - 1))
// whose exponent is <= 0, and whose prefactor tends to 1 / (2 pi) * 1/2 as kappa -> 0 (uniform 1 / (4 pi)).
//
// Band factors: the SH expansion of a normalised zonal lobe is g = sum_l Lambda_l sqrt((2l+1)/(4 pi))
// Y_l0(n.mu) with Lambda_l = 2 pi integral g(t) P_l(t) dt (Funk-Hecke), which for the vMF is exactly
//     Lambda_l(kappa) = I_{l+1/2}(kappa) / I_{1/2}(kappa)
// (modified Bessel functions of the first kind). [Han07] Eq. (7.19) approximates it by exp(-l^2 / (2 kappa)),
// which is far off for small kappa (Lambda_1(1) = 0.313 vs 0.607). Deviation [Han07]: we use the exact
// ratio: by backward recurrence on rho_l = I_{l+1/2} / I_{l-1/2} = kappa / ((2l + 1) + kappa rho_{l+1}) for small
// kappa, forward from Lambda_1 = coth(kappa) - 1/kappa where kappa >= max(8, L^2 / 2), and by Hankel's expansion
// for very large kappa (vmf_lobe.cpp; test: VmfLobe.BandFactorsMatchQuadrature).
#pragma once

#include <span>

#include "libbake/core/eigen.h"

namespace mbk {

// A(kappa) = coth(kappa) - 1/kappa, the length of a vMF's mean vector, for kappa >= 0 (A(0) = 0).
// Accurate to a few ulps: below kappa = 2 from a series without cancellation (the closed form cancels there).
double vmf_mean_length(double kappa);
// 1 - A(kappa), accurate where A is close to 1.
double vmf_one_minus_mean_length(double kappa);

// The closed-form approximation of A^-1 of Banerjee et al. 2005, kappa ~ (3r - r^3) / (1 - r^2)
// ([Han07] Alg. 7.1 line 12). Up to ~5% off (at r ~ 0.5...0.9); used only to start the Newton solve.
double vmf_kappa_closed_form(double r);

// kappa with A(kappa) = r, by Newton's method guarded by the bracket [3 r, 1 / (1 - r)] (A(k) <= k/3 and
// A(k) >= 1 - 1/k), falling back to bisection when a step leaves it; relative accuracy ~1e-15 for r in
// [1e-300, 1 - 1e-16]. r <= 0 gives 0 (a uniform lobe). The r -> 1 cap is explicit: r >= A(kappa_max)
// (including r >= 1, identical normals) gives kappa_max. Error(runtime_failure) for NaN r.
double vmf_kappa_from_mean_length(double r, double kappa_max);

// log g(n; kappa, mu) from cos = mu.n, for kappa >= 0: log(kappa / (2 pi (1 - exp(-2 kappa)))) + kappa (cos - 1).
double vmf_log_density(double kappa, double cos_angle);

// The cosine of the angle from mu of a direction drawn from the lobe by u in [0, 1): the exact inverse of its
// distribution function, cos = 1 + log(1 + u (e^{-2 kappa} - 1)) / kappa (log1p and expm1: no cancellation near the
// axis), clamped to [-1, 1]; kappa below 1e-9 gives the uniform 1 - 2 u. The azimuth is uniform and independent.
double vmf_cos_from_uniform(double kappa, double u);

// Lambda_l(kappa) = I_{l+1/2}(kappa) / I_{1/2}(kappa) for l = 0..out.size()-1; Lambda_0 = 1; kappa = 0 gives
// 0 for l >= 1; kappa = +inf gives 1. Relative accuracy ~1e-14 (tests compare with quadrature to 1e-10).
void vmf_band_factors(double kappa, std::span<double> out);

// A lobe as shaders use it, decoded from the premultiplied storage (alpha, alpha r) of vMF assets
// (formats/SPEC.md "Kind 5"): kappa = A^-1(|r|) capped at kappa_max, mu = r / |r| (+z for r = 0).
// alpha <= 0 (or NaN) is an empty lobe: alpha 0, kappa 0.
struct VmfLobeShape {
  double alpha = 0.0, kappa = 0.0;
  Vec3 mu = Vec3::UnitZ();
};
VmfLobeShape vmf_lobe_from_premultiplied(double alpha, const Vec3& alpha_r, double kappa_max);
// The same lobe's direction only (no concentration to solve for): mu = r / |r|, +z for r = 0; alpha > 0.
Vec3 vmf_direction_from_premultiplied(double alpha, const Vec3& alpha_r);

}  // namespace mbk
