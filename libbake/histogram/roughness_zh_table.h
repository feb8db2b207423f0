// Zonal harmonics of the histogram effect's mirrored roughness lobes for spatially varying roughness ([Shah24]
// Secs. 4.3.1-4.3.3, Eq. 13).
//
// Reflected lobes. Environment light reaches the histogram effect through the mirror images of the lobes
// (reflected_lobe.h): under w_i = 2 (w_h.v) w_h - v angles from the lobe's axis double (in the plane of incidence), so
// a lobe of roughness s mirrors into one of concentration kappa_r = 1 / (4 s^2). The table holds the band factors of
// these reflected lobes (roughness_lobe.h's G_r with kappa_r).
//
// Zonal harmonics. A normalised zonal lobe g(w . mu) has f_l^0 = Lambda_l sqrt((2l + 1) / (4 pi)) with
//     Lambda_l = 2 pi integral_{-1}^{1} g(t) P_l(t) dt   (Funk-Hecke; Lambda_0 = 1),
// and rotated to a unit direction w its SH coefficients are, by Eq. 13, g_l^m = f_l^0 Y_l^m(w) sqrt(4 pi / (2l + 1))
// = Lambda_l Y_l^m(w) (band_radiance_grid.h dots them with the lighting). For the vMF lobe Lambda_l is the Bessel
// ratio I_{l+1/2}(kappa) / I_{1/2}(kappa), exact to ~1e-14 (vmf_band_factors); the test RoughnessZhTable.
// RowsMatchQuadratureOfTheLobe checks every row against a quadrature of the lobe's profile, independent of it.
// 1001 roughnesses s_k = k / 1000 (k = 0 is the mirror lobe, Lambda_l = 1), linearly interpolated between the two
// nearest ([Shah24] Sec. 4.3.3: "1000 uniformly distributed points"); at order 60 the table is 1001 x 61 doubles
// (488 KB; the paper's 240 KB is f32).
#pragma once

#include <span>
#include <vector>

namespace mbk {

class RoughnessZhTable {
 public:
  static constexpr int kSteps = 1000;  // s_k = k / kSteps, k = 0..kSteps

  // 0 <= order <= kMaxShOrder (libbake/core/sh_basis.h), else Error(runtime_failure).
  explicit RoughnessZhTable(int order);
  int order() const { return order_; }
  // Lambda_l of the reflected lobe of roughness s (clamped to [0, 1]) for l = 0..order (out.size() >= order + 1).
  void band_factors(double s, std::span<double> out) const;
  // The same at a tabulated roughness k / kSteps, as computed (no interpolation).
  std::span<const double> row(int k) const;

 private:
  int order_;
  std::vector<double> lambda_;  // [k * (order + 1) + l]
};

// The narrowest roughness whose reflected lobe an expansion of order L holds well enough: Lambda_L(kappa_r) = e^{-2}
// (13.5%) in the large-l form Lambda_l ~ exp(-l (l + 1) / (2 kappa_r)), i.e. 2 s^2 L (L + 1) = 2: s = 1 /
// sqrt(L (L + 1)) (0.0244 at L = 40). A narrower lobe truncated at L rings: negative lobes around a small bright
// light, black after clamping. Shaders widen it to this instead, so a reflection too sharp for the order is blurred,
// not ringing (measured on examples/scenes/histogram.json at order 40, block L1 against the reference: 0.0138
// ringing with black holes, 0.0199 at e^{-2}, 0.0146 at e^{-1} with dark streaks left, 0.039 at e^{-4}).
double narrowest_resolved_roughness(int order);

}  // namespace mbk
