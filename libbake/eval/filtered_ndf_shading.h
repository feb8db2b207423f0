// Shading with a filtered normal distribution: what the `sh`, `vmf` and `toksvig` effects evaluate per pixel
// ([Han07] Secs. 7.3-7.6; [Toksvig05]). All functions work in the tangent frame of the normal map (the frame of
// libbake/image/normal_map.h), on radially symmetric BRDFs f(w . n) ([Han07] Eq. 7.3): w = l for Lambertian
// (f(u) = max(u, 0)), w = h = (l + v) / |l + v| for Blinn-Phong or microfacet lobes.
//
// Convolution ([Han07] Eqs. 7.10, 7.11): the filtered BRDF of a texel with NDF g is
//     r_eff(w) = integral f(w . n) g(n) dn = sum_l rhat_l sum_m g_lm Y_lm(w),   rhat_l = sqrt(4 pi / (2l + 1)) f_l,
// with f_l = 2 pi integral_{-1}^{1} f(t) Y_l0(t) dt the zonal coefficients of f (Ramamoorthi-Hanrahan
// normalisation: for f = max(u, 0), rhat = (pi, 2 pi / 3, pi / 4, 0, ...)). SH basis: libbake/core/sh_basis.h.
//
// Roughness conventions: Blinn-Phong exponent s of the normalised lobe (s + 1) / (2 pi) (h . n)^s ([Han07]
// Eq. 7.20); microfacet lobes in the renderer's Beckmann alpha (libbake/eval/microfacet_brdf.h: each slope
// component has variance alpha^2 / 2). A vMF lobe of concentration kappa spreads each angular component by
// variance 1 / kappa, so Beckmann alpha filters to alpha'^2 = alpha^2 + 2 / kappa ([Han07] Eq. 7.21 with
// sigma^2 = alpha^2 / 4) and Blinn-Phong s to s' = kappa s / (kappa + s) (Eq. 7.20).
#pragma once

#include <algorithm>
#include <functional>
#include <span>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/core/sh_basis.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/eval/microfacet_brdf.h"

namespace mbk {

// rhat_l for l = 0..order of f(t), t = cos(angle) in [-1, 1], by Gauss-Legendre on [-1, 0] and [0, 1]
// separately (so a kink at t = 0, as in max(u, 0), costs no accuracy); exact for polynomials of degree
// <= 2 (order + 32) - 1 - order on each half.
std::vector<double> zonal_brdf_coefficients(const std::function<double(double)>& f, int order);
// rhat_l of the clamped cosine max(t, 0): (pi, 2 pi / 3, pi / 4, 0, -pi / 24, ...).
std::vector<double> lambertian_rhat(int order);
// rhat_l of a microfacet distribution D(t) (microfacet_brdf.h; 0 for t <= 0), the zonal lobe the sh and vmf
// shaders convolve with the NDF. D is normalised as a projected area, so rhat_1 = 2 pi integral D(t) t dt = 1.
// Sharp lobes (alpha down to 0.01) are integrated on a composite rule graded towards t = 1, where they live.
std::vector<double> microfacet_rhat(const MicrofacetLobe& lobe, int order);

// [Han07] Eq. (7.12): sum_l window_l rhat_l sum_m g_lm Y_lm(w) for SH NDF coefficients g (order from basis,
// g.size() >= basis.count()), window and rhat of size >= order + 1.
double sh_filtered_brdf(const ShBasisEvaluator& basis, std::span<const double> g, std::span<const double> window,
                        std::span<const double> rhat, const Vec3& w);

// The SH coefficients of the NDF of one normal n (a finest texel): Y_lm(n), into g.
void delta_ndf_coefficients(const ShBasisEvaluator& basis, const Vec3& n, std::span<double> g);

// [Han07] Eq. (7.14) with exact band factors: sum_j alpha_j sum_l rhat_l Lambda_l(kappa_j) (2l + 1) / (4 pi)
// P_l(w . mu_j), Lambda_l the Bessel ratios of libbake/core/vmf_lobe.h (not Eq. 7.19's exp(-l^2 / 2 kappa)).
double vmf_filtered_brdf(std::span<const VmfLobeShape> lobes, std::span<const double> rhat, const Vec3& w);
// The per-lobe factor of Eqs. (7.14) and (7.23): rhat_l Lambda_l(kappa) for l = 0..rhat.size() - 1. Shaders compute
// it once per lobe per pixel and reuse it for every light and colour channel (the band factors are the costly part).
std::vector<double> vmf_filtered_rhat(std::span<const double> rhat, double kappa);
// Eq. (7.14) with filtered[j] = vmf_filtered_rhat(rhat, lobes[j].kappa) precomputed (same result as above).
double vmf_filtered_brdf(std::span<const VmfLobeShape> lobes, std::span<const std::vector<double>> filtered,
                         const Vec3& w);

// [Han07] Eq. (7.20): the exponent of a normalised Blinn-Phong lobe of exponent s convolved with a vMF lobe.
double vmf_filtered_blinn_phong_exponent(double s, double kappa);
// (s + 1) / (2 pi) max(t, 0)^s.
double blinn_phong_lobe(double s, double t);
// [Han07] Eq. (7.21) in Beckmann alpha: sqrt(alpha^2 + 2 / kappa) (alpha itself for kappa = +inf).
double vmf_filtered_beckmann_alpha(double alpha, double kappa);

// [Toksvig05]: the mean of unit normals of length |n| < 1 reads as a Gaussian spread of variance
// sigma^2 = (1 - |n|) / |n| per axis; Blinn-Phong s -> s / (1 + s sigma^2), Beckmann alpha^2 -> alpha^2 + 2 sigma^2.
// A zero-length (or NaN) mean gives +inf (no lobe left).
double toksvig_variance(double mean_length);
double toksvig_blinn_phong_exponent(double s, double mean_length);
double toksvig_beckmann_alpha(double alpha, double mean_length);

// The largest microfacet alpha the filtered-NDF shaders hand to the BRDF. Toksvig's variance and 2 / kappa grow
// without bound where normals cancel (kappa = 0 is a uniform lobe), and without the cap GGX's D is NaN at
// alpha = inf (inf / inf) while Beckmann's vanishes; alpha = 1 (a slope deviation of 0.7 per axis) is already a
// near-flat lobe and the roughest a scene may ask for (test: FilteredNdfEffects.CancellingNormalsStayFinite).
inline constexpr double kMaxFilteredAlpha = 1.0;
// The roughness a filtered shader hands to the BRDF: the widened alpha capped at kMaxFilteredAlpha, never below
// the material's own alpha (a material rougher than the cap keeps its roughness). NaN widened gives the cap.
inline double clamp_filtered_alpha(double alpha, double widened) {
  return std::max(alpha, std::min(kMaxFilteredAlpha, widened));
}

// [Han07] Eq. (7.23): the shading of one vMF lobe (kappa, mu) under distant light given as SH coefficients light_lm
// (one channel; order from light.size() = (L + 1)^2):
//     B = sum_l rhat_l Lambda_l(kappa) sum_m light_lm Y_lm(mu).
// With Lambertian rhat this is the filtered irradiance (the vmf shader's distant diffuse). Eq. (7.24), the same
// sum for specular light reparameterised about the half vector, is not implemented: the shaders use the
// renderer's distant-specular lobe instead (deviation [Han07], stated in sh_effect.h and vmf_effect.h).
double vmf_sh_lighting(std::span<const double> light, std::span<const double> rhat, double kappa, const Vec3& mu);
// The same with filtered = vmf_filtered_rhat(rhat, kappa) and y_mu = Y_lm(mu) (size >= light.size()) precomputed.
double vmf_sh_lighting(std::span<const double> light, std::span<const double> filtered, std::span<const double> y_mu);

}  // namespace mbk
