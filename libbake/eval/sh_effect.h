// The evaluator side of the `sh` effect (libbake/scene/effect_sh.cpp; [Han07] Secs. 7.3-7.4): every pixel
// shades with the SH coefficients g_lm of the normal distribution under its footprint, looked up trilinearly
// in the baked `sh` asset at the footprint's LOD (filtered_ndf_textures.h; read through formats/ only). With
// the tangent frame of the hit (x = +u, y = +v, z = the surface normal; directions below in that frame):
//
//   diffuse, per point/directional light l:  albedo / pi * max(0, sum_l w_l A_l sum_m g_lm Y_lm(l))     Eq. (7.12)
//     A_l the clamped cosine's rhat (pi, 2 pi / 3, pi / 4, 0, -pi / 24, ...), w_l the asset's window;
//   specular, per light: the lookups' finest-level parts are single normals (the renormalised bilinear normal,
//     weight 1 - t of each trilinear probe) and shade exactly as the reference shades a normal (lobe_specular.h's
//     product at that normal with the material's own alpha; a deviation from [Han07], which lets them through the
//     expansion: on a long footprint a few such normals became one lobe widened by their spread, whose masking at
//     a grazing view halved a point light's highlight). The rest of the NDF, g_rest = g - sum_d w_d Y(n_d), shades
//     as F G2(l, v) D_g(h) / (4 (n.l)(n.v)) with the filtered distribution
//     D_g(h) = max(0, sum_l D_l sum_m g_lm Y_lm(h)) + tail(h)                                             Eq. (7.12)
//     D_l the rhat of the material's D(cos) (GGX or Beckmann, microfacet_rhat), the bands unwindowed and those
//     beyond the order completed from the vMF lobe of the mean (sh_lobe_tail.h), and F, G2 and the
//     denominators evaluated at the mean normal n = (g_11, g_1-1, g_10) / sqrt(3 / (4 pi)), normalised
//     (the paper's "radially symmetric lobe times a factor of l and v"; [Han07] Sec. 7.3). G2 is that of the
//     lobe widened by Toksvig's variance of |mean| (the filtered surface is rougher, and at grazing angles
//     its masking matters: with the base alpha the far field of a receding plane is several times too bright).
//     Where the vMF lobe of the mean (kappa = A^-1(|mean|)) is wide against the view's or the light's horizon
//     (lobe_specular.h), that product is corrected by the lobe: lobe_corrected_specular(product, the lobe's own
//     product with its D through every band, the lobe's integral) - a deviation from [Han07], whose product is
//     2-10x too dark on a rough far field at grazing angles;
//   distant lighting (order-2 SH): diffuse = albedo / pi * integral g_2(n) E(n) dn, g_2 the NDF's bands
//     l <= 2 and E the renderer's irradiance, by a product quadrature exact for degree 4 (the integral is
//     the SH dot product rotated into the tangent frame, Eq. (7.23); exact where E >= 0, which the renderer
//     clamps); specular = the renderer's vMF lobe at n's mirror direction, widened with Toksvig's variance
//     of |mean normal| (deviation [Han07]: the half-vector reparameterisation of Eq. (7.24) would need a
//     per-pixel projection of the lighting; an order-2 environment carries no detail it would resolve).
//
// Roughness convention: the renderer's microfacet alpha (microfacet_brdf.h), used unchanged in D_l (the NDF
// does the widening); G2's and the distant lobe's alpha' = sqrt(alpha^2 + 2 sigma^2) as in toksvig_effect.h. At level 0
// the lookup is one delta at the renormalised bilinear normal (filtered_ndf_textures.h), so the image equals plain
// normal mapping up to the truncation of D at the asset's order: at order 24 within 1% on gentle bumps (test:
// FilteredNdfEffects.FinestLevelEqualsPlainNormalMapping) and within 0.5% of the mean radiance on a bumpy map
// (FilteredNdfEffects.MagnifiedBumpyMapMatchesPlainNormalMapping); a low order blurs sharp
// highlights (truncation) at every level. Reference mode: `base` (the raw map supersampled is the ground truth).
//
// Shader port: per pixel, (L+1)^2 coefficients from the trilinear fetch, two SH evaluations (at l and h)
// per light, rhat tables precomputed per material.
#pragma once

#include "libbake/eval/effect_shaders.h"

namespace mbk {

ShaderPtr sh_effect_shader(const EffectShaderRequest& request);

}  // namespace mbk
