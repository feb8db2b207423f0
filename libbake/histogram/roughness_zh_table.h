// The intrinsic-roughness lobe of the histogram effect and its zonal harmonics for spatially varying roughness
// ([Shah24] Secs. 4.3.1-4.3.3, Eqs. 2, 12, 13).
//
// The lobe. G_r(w; mu, sigma) of Eq. 2 is the spherical Gaussian (von Mises-Fisher lobe, libbake/core/vmf_lobe.h)
//     G_r(w; mu, sigma) = kappa / (2 pi (1 - e^{-2 kappa})) e^{kappa (w.mu - 1)},   kappa = 1 / sigma^2,
// normalised over the sphere; for small sigma it is the Gaussian e^{-theta^2 / (2 sigma^2)} / (2 pi sigma^2) of
// the angle theta between w and mu. Roughness sigma is in (0, 1] as in the paper.
//
// Reflected lobes. Environment light reaches the histogram effect through the mirror directions of the lobes
// (histogram_effect.h): under the reflection w_i = 2 (w_h.v) w_h - v angles from the lobe's axis double, so a lobe of
// kappa around mu in half-vector space becomes, to first order (the spherical warp of Wang et al. 2009, isotropic),
// a lobe of kappa / 4 around the mirror direction of mu. The table below therefore holds the band factors of the
// REFLECTED lobe, kappa_r(sigma) = 1 / (4 sigma^2).
//
// Zonal harmonics. A normalised zonal lobe g(w . mu) has f_l^0 = Lambda_l sqrt((2l + 1) / (4 pi)) with
//     Lambda_l = 2 pi integral_{-1}^{1} g(t) P_l(t) dt   (Funk-Hecke; Lambda_0 = 1),
// and rotated to a unit direction w its SH coefficients are, by Eq. 13,
//     g_l^m = f_l^0 Y_l^m(w) sqrt(4 pi / (2l + 1)) = Lambda_l Y_l^m(w).
// The table is computed by quadrature of the lobe's profile (so any zonal lobe could take the vMF's place): with
// u = kappa (1 - t), Lambda_l = integral_0^U e^{-u} P_l(1 - u / kappa) du / integral_0^U e^{-u} du, U = min(2 kappa,
// 60) (e^{-60} is below a double's resolution of the sum), composite Gauss-Legendre with panels fine enough for
// e^{-u} and for P_l's oscillation (test: RoughnessZhTable.MatchesTheBesselRatios, against the closed form
// I_{l+1/2} / I_{1/2} of vmf_lobe.h). 1001 roughnesses sigma_k = k / 1000 (k = 0 is the mirror lobe, Lambda_l = 1),
// linearly interpolated between the two nearest ([Shah24] Sec. 4.3.3: "1000 uniformly distributed points"); at
// order 60 the table is 1001 x 61 doubles (488 KB; the paper's 240 KB is f32).
#pragma once

#include <span>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/core/sh_basis.h"

namespace mbk {

inline constexpr double kMinLobeRoughness = 1e-3;  // sigma below this is taken as this (a finite lobe)

// kappa = 1 / sigma^2 of the lobe, sigma clamped to [kMinLobeRoughness, 1].
double lobe_kappa(double sigma);
// G_r(w; mu, sigma) from cos = w . mu (Eq. 2's lobe).
double roughness_lobe(double cos_angle, double sigma);
// A direction drawn from G_r(.; mu, sigma) by two uniform numbers in [0, 1): exact inversion of the vMF's
// cos-angle distribution, cos = 1 + log(u1 + (1 - u1) e^{-2 kappa}) / kappa, and a uniform azimuth.
Vec3 sample_roughness_lobe(const Vec3& mu, double sigma, double u1, double u2);

class RoughnessZhTable {
 public:
  static constexpr int kSteps = 1000;  // sigma_k = k / kSteps, k = 0..kSteps

  // 0 <= order <= kMaxShOrder, else Error(runtime_failure).
  explicit RoughnessZhTable(int order);
  int order() const { return order_; }
  // Lambda_l of the reflected lobe of roughness sigma (clamped to [0, 1]) for l = 0..order (out.size() >= order + 1).
  void band_factors(double sigma, std::span<double> out) const;
  // The same at a tabulated roughness k / kSteps, as computed (no interpolation).
  std::span<const double> row(int k) const;

 private:
  int order_;
  std::vector<double> lambda_;  // [k * (order + 1) + l]
};

// Lambda_l (l = 0..L) of the normalised zonal lobe e^{kappa (t - 1)} by quadrature (see above); kappa > 0, or +inf
// for the mirror lobe (every Lambda_l = 1).
void zonal_lobe_band_factors(double kappa, std::span<double> out);

// The narrowest roughness whose reflected lobe an expansion of order L holds well enough: Lambda_L(kappa_r) = e^{-2}
// (13.5%), i.e. 2 sigma^2 L (L + 1) = 2 with Lambda_l ~ exp(-l (l + 1) / (2 kappa_r)): sigma = 1 / sqrt(L (L + 1))
// (0.0244 at L = 40). A narrower lobe truncated at L rings: negative lobes around a small bright light, black after
// clamping. Shaders widen it to this instead, so a reflection too sharp for the order is blurred, not ringing
// (measured on examples/scenes/histogram.json at order 40, block L1 against the reference: 0.0138 ringing with
// black holes, 0.0199 at e^{-2}, 0.0146 at e^{-1} with dark streaks left, 0.039 at e^{-4}).
double narrowest_resolved_roughness(int order);

// Eq. 13: the SH coefficients (k = sh_index(l, m) < basis.count()) of the zonal lobe with band factors `lambda`
// rotated to the unit direction w: g_lm = Lambda_l Y_lm(w), accumulated as out[k] += weight g_lm.
void add_rotated_zonal_lobe(const ShBasisEvaluator& basis, const Vec3& w, std::span<const double> lambda, double weight,
                            std::span<double> out, std::span<double> scratch);

}  // namespace mbk
