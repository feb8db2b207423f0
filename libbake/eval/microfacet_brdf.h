// The BRDF of every material: Lambertian diffuse plus a single-scattering microfacet specular lobe
// (Walter et al., "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007; Heitz,
// "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 2014):
//
//     f(l, v) = albedo / pi  +  D(h) G2(l, v) F(v . h) / (4 (n . l)(n . v)),   h = (l + v) / |l + v|
//
// Roughness convention: `alpha` is the width parameter of the distribution itself, used as given (no
// perceptual remapping such as alpha = roughness^2). For Beckmann, alpha^2 / 2 is the variance of each
// slope component; GGX uses the same alpha for the same half-width at small alpha.
//   Beckmann  D = exp(-tan^2(th) / alpha^2) / (pi alpha^2 cos^4(th))
//             Lambda(a) = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)),  a = 1 / (alpha tan(th))
//   GGX       D = alpha^2 / (pi (cos^2(th) (alpha^2 - 1) + 1)^2)
//             Lambda = (-1 + sqrt(1 + alpha^2 tan^2(th))) / 2
// Both D are normalised as projected areas: integral of D(m) (n . m) over the hemisphere = 1.
// Masking-shadowing: the height-correlated Smith form G2 = 1 / (1 + Lambda(l) + Lambda(v)) [Heitz14, Eq. 99];
// G1 = 1 / (1 + Lambda). Fresnel: Schlick, F = F0 + (1 - F0)(1 - v . h)^5.
// Directions are unit vectors pointing away from the surface; f is 0 when l or v is below the horizon of n.
#pragma once

#include <functional>

#include "libbake/core/eigen.h"
#include "libbake/scene/scene.h"

namespace mbk {

struct MicrofacetLobe {
  Distribution distribution = Distribution::ggx;
  double alpha = 0.5;
};

// D(m) for a microfacet normal at cos(th) = n . m; 0 for cos <= 0.
double microfacet_d(const MicrofacetLobe& lobe, double cos_theta);
// Smith's Lambda for a direction at cos(th) from the normal (0 at the normal, growing towards the horizon).
double smith_lambda(const MicrofacetLobe& lobe, double cos_theta);
double smith_g1(const MicrofacetLobe& lobe, double cos_theta);
double smith_g2(const MicrofacetLobe& lobe, double cos_l, double cos_v);
Vec3 schlick_fresnel(const Vec3& f0, double cos_d);

struct Brdf {
  Vec3 albedo = Vec3::Zero();
  Vec3 f0 = Vec3::Zero();
  MicrofacetLobe lobe;
  static Brdf of(const Material& m) { return {m.albedo, m.f0, {m.distribution, m.roughness}}; }
};

// f(l, v) around the unit normal n, per RGB channel.
Vec3 evaluate_brdf(const Brdf& brdf, const Vec3& n, const Vec3& l, const Vec3& v);
// The specular term alone (the diffuse one is albedo / pi wherever both directions are above the horizon).
Vec3 evaluate_specular(const Brdf& brdf, const Vec3& n, const Vec3& l, const Vec3& v);
// The same with another distribution: D(h) from `d` (given the unit half vector h) in place of the lobe's, G2
// and F as above (e.g. a glint P-NDF, libbake/glint/glint_pndf.h, under the lobe's masking-shadowing).
Vec3 evaluate_specular(const Brdf& brdf, const Vec3& n, const Vec3& l, const Vec3& v,
                       const std::function<double(const Vec3& h)>& d);

}  // namespace mbk
