// The evaluator side of the `histogram` effect (libbake/scene/effect_histogram.cpp; [Shah24]): the specular of
// every light comes from the footprint's binned P-NDF (Eq. 3) with a spatially varying intrinsic roughness sigma
// (roughness_texture.h); the diffuse is shaded around the macro-surface normal, as the glints effect does. With the
// tangent frame of the hit (x = +u, y = +v, z = the macro normal n), bin b's direction w_b (its theta centre and phi
// centre 2 pi (i + 1/2) / N) and P_b the footprint's probability of bin b:
//
//   D(h) = sum_b P_b G_r(h; w_b, sigma)                                     (Eq. 3; G_r in roughness_zh_table.h)
//
// filtered   P_b from the baked asset over the pixel's footprint: its anisotropic probes (uv_footprint.h), each a
//            square of the probe's width in texels (binned_ndf_source.h), equally weighted.
//            Point and directional lights: the material's BRDF with D replaced (microfacet_brdf.h evaluate_specular:
//            F and G2 of the material, its f0 and base roughness).
//            Distant light (environment maps and skies): L = sum_b P_b F(v.w_b) G2(n.r_b, n.v) (v.w_b) / (n.v)
//            * integral L_i(w) G'_b(w) dw, the integral over the reflected lobe G'_b of bin b, whose axis is the
//            mirror direction r_b = 2 (v.w_b) w_b - v and whose band factors are the table's (kappa / 4, the
//            spherical warp; roughness_zh_table.h). With Schlick's F = f0 + (1 - f0) s_b, s_b = (1 - v.w_b)^5, the
//            lobes sum into two SH vectors of order L (Eq. 12 with Eq. 13's rotated zonal lobes)
//                A_lm = sum_b P_b g_b Lambda_l(sigma) Y_lm(r_b),  B_lm = sum_b P_b g_b s_b Lambda_l(sigma) Y_lm(r_b),
//            g_b = G2 (v.w_b) / (n.v), and the radiance is f0 (A . L_SH) + (1 - f0) (B . L_SH) (Eq. 9), L_SH the
//            distant lighting projected to order L (distant_radiance.h). This is the paper's Eqs. 8-9 with the light
//            kept in the world frame (view-independent) and the NDF's lobes warped to reflected directions, instead
//            of a light projection per view direction. Bins whose mirror direction is below the macro surface
//            (n.r_b <= 0) or that face away from the viewer reflect nothing.
// reference  Eq. 2 by Monte Carlo: each of the reference's rays sees the normal of the texel its exact uv falls in
//            (equal weights over the footprint, no binning), point lights through G_r around it, and distant light
//            by kHistogramReferenceLobeSamples directions h drawn from G_r per ray (stratified, seeded by the ray's
//            uv, so `render --seed` moves them): L_i(w_i) F(v.h) G2(n.w_i, n.v) (v.h) / (n.v) with w_i the mirror
//            of v about h and L_i the unprojected distant radiance. It reads the normal map and the roughness
//            texture, never the asset.
#pragma once

#include "libbake/eval/effect_shaders.h"

namespace mbk {

inline constexpr int kHistogramReferenceLobeSamples = 4;

ShaderPtr histogram_effect_shader(const EffectShaderRequest& request);

}  // namespace mbk
