// The mirror image of a half-vector lobe, for environment light through a binned P-NDF (histogram_effect.h).
//
// A lobe G_r(h; w, sigma) of half vectors h around w, seen from the viewer direction v, sends light in the mirror
// directions w_i = 2 (v.h) h - v. To first order in the offset d = h - w (d perpendicular to w), with c = v.w and
// e the unit direction of v's part perpendicular to w (the plane of incidence),
//     dw_i = 2 (e.v) (e.d) w + 2 c d,
// so an offset in the plane of incidence moves w_i by 2 |d| and one across it by 2 c |d|: the mirror image of an
// isotropic lobe of width sigma is an anisotropic one, 2 sigma wide in the plane of incidence and 2 c sigma across
// it (its area 4 c sigma^2 is the Jacobian 4 (v.h) of the reflection). An isotropic warp (2 sigma both ways, the
// usual prefiltered-environment approximation) blurs grazing reflections across the plane by 1 / c.
//
// Zonal harmonics represent only isotropic lobes, so the anisotropic image is written as an average of isotropic
// lobes of the minor width 2 c sigma whose axes are spread along the plane of incidence by a Gaussian of standard
// deviation 2 sigma sqrt(1 - c^2) (the convolution of the two has the major width 2 sigma): K axes at equal steps
// over +-3 standard deviations, Gaussian weights summing to 1 (their variance is the spread's to 0.7% from K = 5),
// steps at most 1.5 times the minor width so the sum has no visible ripple; K = 3 takes the 3-point Gauss-Hermite
// rule (axes at 0 and +-sqrt(3) spreads, weights 2/3 and 1/6), whose variance is exact. Where the spread is at most
// kIsotropicRatio of the minor width (c >= 0.995) one lobe of the mean variance is used. K is capped at
// kMaxReflectedLobes; past the cap (c below ~0.27) the minor width is widened to keep the steps at 1.5 widths and the
// spread narrowed so that the in-plane width stays 2 sigma. The model is first order in sigma: it is meant for
// glossy lobes (sigma up to ~0.25); the spread is capped at kMaxSpread (pi / 6, so the outer axes stay within 90
// degrees of the mirror direction) for broader ones, which it renders narrower than they are.
//
// The integrand's smooth factors (Fresnel, and the Jacobian's v.h in (v.h) / (n.v)) vary to first order across the
// lobe in the plane of incidence: v.h = c cos(delta) + sin(theta_d) sin(delta) for a half-vector offset delta, a tilt
// of sin(theta_d) / c per radian that moves the weighted lobe's centre by 2 sigma^2 sin(theta_d) / c, which is not
// small at grazing angles. Each axis therefore carries the half vector it is the mirror image of (offset delta = half
// its angle from the mirror direction), and shaders evaluate those factors there (a Monte Carlo check against the
// exact reflected integral of a sharp-edged light, sigma 0.1 at 28 degrees elevation: within 1-5% where the
// isotropic warp errs 25-45% and the untilted sum 5-13%).
#pragma once

#include <array>

#include "libbake/core/eigen.h"

namespace mbk {

inline constexpr int kMaxReflectedLobes = 15;
inline constexpr double kIsotropicRatio = 0.1;
inline constexpr double kMaxSpread = 0.52359877559829887;  // pi / 6

struct ReflectedLobes {
  int count = 0;
  // The roughness whose reflected lobe (kappa_r = 1 / (4 s^2), roughness_zh_table.h) has the minor width: the
  // table's row to read for every lobe.
  double table_sigma = 0;
  std::array<Vec3, kMaxReflectedLobes> axes;
  std::array<double, kMaxReflectedLobes> weights;
  std::array<double, kMaxReflectedLobes> view_cosines;  // v.h of the half vector each axis is the mirror image of
};

// The mirror image of G_r(.; w, sigma) for the unit viewer direction v (w.v > 0; unit w).
ReflectedLobes reflected_lobes(const Vec3& w, const Vec3& v, double sigma);

}  // namespace mbk
