// The evaluator side of the `histogram` effect (libbake/scene/effect_histogram.cpp; [Shah24]): the specular of
// every light comes from the footprint's binned P-NDF (Eq. 3) with a spatially varying intrinsic roughness sigma
// (roughness_texture.h); the diffuse is shaded around the macro-surface normal, as the glints effect does. With the
// tangent frame of the hit (x = +u, y = +v, z = the macro normal n), bin b's direction w_b (its theta centre and phi
// centre 2 pi (i + 1/2) / N) and P_b the footprint's probability of bin b:
//
//   D(h) = sum_b P_b G_r(h; w_b, sigma)                                     (Eq. 3; G_r in roughness_lobe.h)
//
// filtered   P_b from the baked asset over the pixel's footprint: its anisotropic probes (uv_footprint.h), each a
//            square of the probe's width in texels (binned_ndf_source.h), equally weighted; the exact integral images
//            of a `histogram` asset, the network of a `neural_histogram` one (neural_binned_ndf.h), or with `method
//            pyramid` a MIP pyramid of histograms built from the exact asset at load (histogram_pyramid_baseline.h).
//            Point and directional lights: the material's BRDF with D replaced (microfacet_brdf.h evaluate_specular:
//            F and G2 of the material, its f0 and base roughness).
//            Distant light (environment maps and skies): L = sum_b P_b F(v.w_b) G2(n.r_b, n.v) (v.w_b) / (n.v)
//            * integral L_i(w) G'_b(w) dw, the integral over the reflected lobe G'_b of bin b, whose axis is the
//            mirror direction r_b = 2 (v.w_b) w_b - v and whose band factors are the table's (kappa / 4, the
//            spherical warp; roughness_zh_table.h), written as a few isotropic zonal lobes i along the plane of
//            incidence (reflected_lobe.h: the mirror image is 2 sigma wide in that plane and 2 (v.w_b) sigma across
//            it), each rotated to its axis r_i by Eq. 13 (g_lm = Lambda_l(sigma_i) Y_lm(r_i)) and dotted with the
//            distant lighting's SH of order L (Eq. 9): sum_lm g_lm L_lm = sum_l Lambda_l B_l(r_i), with the
//            per-band radiance B_l read from a direction grid (band_radiance_grid.h). Summed over the lobes that is
//            Eq. 12's NDF_SH dotted with L_SH, with F (Schlick, f0 + (1 - f0)(1 - v.h_i)^5), G2 and the Jacobian's
//            v.h_i evaluated at each lobe's own half vector h_i. This is the paper's Eqs. 8-9 with the light
//            kept in the world frame (view-independent) and the NDF's lobes mirrored about the view direction,
//            instead of a light projection per view direction. Lobes whose axis is below the macro surface
//            (n.r_i <= 0) or whose half vector faces away from the viewer reflect nothing.
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
