// The specular reflection of a vMF lobe of shading normals under one light: what the reference computes per
// normal, integrated over the lobe. The `vmf` and `toksvig` shaders use it per lobe and light.
//
// A pixel's reference value is the mean over its texels' normals n of
//     Phi(n) = f_s(l, v; n') (n' . l)_+ = D(h . n') G2(n' . l, n' . v) F(v . h) / (4 n' . v),  n' = facing_viewer(n, v)
// with the material's D and G2 (microfacet_brdf.h) and n' the normal bent towards the viewer (scene_lighting.h).
// For a lobe p = vMF(mu, kappa) of normals (vmf_lobe.h) the filtered value is S = integral p(n) Phi(n) dn.
//
// Where the lobe is narrow against the geometry - its angular spread sqrt(2 / kappa) under a third of the cosines
// of mu to the view's and the light's horizons - Phi's factors other than D hardly vary over it and S is [Han07]'s
// evaluation: D widened to alpha' = sqrt(alpha^2 + 2 / kappa) (Eq. 7.21, filtered_ndf_shading.h) around mu, and
// G2, F and the denominators at mu (the near field, unchanged). Elsewhere that product is not the mean: 1 / (n . v)
// and G2 vary by orders of magnitude over a lobe that reaches a horizon, and the normals behind the view horizon
// are bent onto it, where they reflect the most (a grazing highlight of a rough far field is 2-10x brighter in the
// reference than the product says). There the wide lobes of a pixel are integrated together, S = integral
// sum_j w_j p_j(n) Phi(n) dn, by multiple importance sampling with the balance heuristic over three point sets:
// K points of each wide lobe p_j, K points of the material's D(m) (m . h) around h (kept in front of the view
// horizon), and K points behind the view horizon (cylindrical coordinates about v: the azimuth from a wrapped
// Cauchy about h's, n . v from an exponential leaning like the lobes) for the bent normals no other set reaches
// well. Each set is the same Fibonacci lattice mapped by exact inverse CDFs, so S is a smooth, noise-free function
// of the lobes, l and v. Cost: (J + 2) K evaluations of D and G2 per light where lobes are wide (F once), none
// extra elsewhere: the receding plane's render takes 1.4x the CPU time of the product alone. Accuracy (test
// LobeSpecular.MatchesTheLobesMeanOfTheReferenceShading, 24 view/light configurations from 2 degrees up, kappa 3-40):
// 2-4% of the lobe's mean at K = 13 where the product errs 40-80%.
#pragma once

#include <cmath>
#include <span>

#include "libbake/core/eigen.h"
#include "libbake/eval/microfacet_brdf.h"

namespace mbk {

// K, the points of each point set (a Fibonacci number), and the one before it, the lattice's generator.
inline constexpr int kLobeSpecularPoints = 13;
inline constexpr int kLobeSpecularGenerator = 8;

// One lobe of shading normals: weight (the mixture's alpha_j), unit mean mu as the texels hold it (unbent; world or
// tangent space, like l and v), concentration kappa in [0, +inf] (+inf: one normal), and the material's alpha
// widened by the lobe and capped (filtered_ndf_shading.h clamp_filtered_alpha), used where the lobe is narrow.
struct SpecularLobe {
  double weight = 1.0;
  Vec3 mu = Vec3::UnitZ();
  double kappa = INFINITY;
  double widened_alpha = 0.0;
};

// S = sum_j weight_j S_j per RGB channel for unit l and v: narrow lobes by [Han07]'s widened lobe, the others
// integrated together (their points shared through the mixture's density).
Vec3 lobes_specular(const Brdf& brdf, std::span<const SpecularLobe> lobes, const Vec3& l, const Vec3& v);

// The same, every lobe integrated (tests compare the two paths; lobes of kappa = +inf are not allowed here).
Vec3 lobes_specular_integrated(const Brdf& brdf, std::span<const SpecularLobe> lobes, const Vec3& l, const Vec3& v);

// Whether lobes_specular takes [Han07]'s product for this lobe (one normal, or narrow against the geometry), rather
// than integrating it.
bool lobe_specular_is_product(const SpecularLobe& lobe, const Vec3& l, const Vec3& v);

// The specular of an NDF that is not a vMF lobe, known only as a product - `product`, its own D at h times every
// other factor at its mean normal (the `sh` shader's Eq. 7.12) - corrected with the vMF lobe of the same mean (and
// mean length) where that lobe is wide: `lobe_product` is the lobe's specular by the same product (its D through the
// same expansion, the same other factors) and `lobe_integrated` its integral over the lobe (lobes_specular). Per
// channel, with p, q, I these three:
//     p <  q:  p I / q      (the share of the lobe's D the NDF has at h gets the lobe's geometric correction I / q)
//     p >= q:  I + (p - q)  (the lobe's integral, plus the NDF's excess over the lobe, e.g. a second cluster of
//                            normals, left as a product: nothing says how the lobe's correction applies to it)
// So a vMF NDF (p = q) shades as its integral (also where q = 0: the normals bent onto the view horizon reflect
// what no product sees), a lobe without correction (I = q) leaves p unchanged, the result is continuous in p
// (for q > 0), at most I + p, and nothing is divided by 0.
Vec3 lobe_corrected_specular(const Vec3& product, const Vec3& lobe_product, const Vec3& lobe_integrated);

}  // namespace mbk
