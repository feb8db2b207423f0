// The distant lighting's radiance band by band on a direction grid, so that a zonal lobe's reflected radiance costs a
// bilinear lookup instead of an SH basis evaluation ([Shah24] Sec. 4.3.2 precomputes the basis functions densely for
// the same reason).
//
// For SH lighting L_lm of order L, the radiance a normalised zonal lobe with band factors Lambda_l reflects from
// direction r is, by Eq. 13 and the SH dot product of Eq. 9,
//     sum_lm L_lm Lambda_l Y_lm(r) = sum_l Lambda_l B_l(r),     B_l(r) = sum_m L_lm Y_lm(r)  (RGB, l = 0..L).
// B_l is stored at the nodes of a lat-long grid (the conventions of sh_lighting.h: theta from +Y, phi = atan2(z, x))
// with theta_j = pi j / (R - 1), j = 0..R-1 (both poles) and phi_i = 2 pi i / C, C = 2 (R - 1), R - 1 = 4 L (a step of
// pi / (4 L)), and read bilinearly (phi wrapping). B_l oscillates at most ~l times around a great circle, so the
// interpolation errs by about (pi l / (4 L))^2 / 8 of band l's amplitude per axis (<= 7.7% on the highest band, up to
// twice that in the two axes together), and every lobe the shader uses attenuates the highest band to <= e^{-2}
// (narrowest_resolved_roughness): test BandRadianceGrid.LookupsMatchTheDirectSum (random lighting, lobes and
// directions, against that bound). Built in parallel by rows; at order 40 the grid holds 161 x 320 x 41 RGB floats
// (25 MB), at 64 257 x 512 x 65 (103 MB).
#pragma once

#include <span>
#include <vector>

#include "libbake/core/eigen.h"

namespace mbk {

class BandRadianceGrid {
 public:
  // light_sh: (L + 1)^2 RGB coefficients (k = l (l + 1) + m), L >= 0.
  explicit BandRadianceGrid(const std::vector<Vec3>& light_sh);
  int order() const { return order_; }
  // sum_l lambda[l] B_l(r) at the unit direction r; lambda holds order() + 1 band factors. Not clamped.
  Vec3 lobe_radiance(const Vec3& r, std::span<const double> lambda) const;

 private:
  int order_ = 0;
  int rows_ = 0, columns_ = 0;
  std::vector<float> bands_;  // [row][column][l][rgb]
};

}  // namespace mbk
