// The evaluator side of the `vmf` effect (libbake/scene/effect_vmf.cpp; [Han07] Secs. 7.5-7.6): every pixel
// shades with the J vMF lobes (alpha_j, kappa_j, mu_j) of the normal distribution under its footprint, looked up
// in the baked `vmf` asset at the footprint's LOD by Alg. 7.2 (trilinear blend of (alpha, alpha r) per lobe slot,
// filtered_ndf_textures.h; read through formats/ only). Each mu_j is turned into world space by the hit's
// tangent frame and bent towards the viewer like any shading normal (scene_lighting.h facing_viewer). Then:
//
//   diffuse, per point/directional light l:
//     albedo / pi * max(0, sum_j alpha_j sum_l A_l Lambda_l(kappa_j) (2l + 1) / (4 pi) P_l(l . mu_j))  Eq. (7.14)
//     with A_l the clamped cosine's rhat to order kVmfDiffuseOrder and the exact Bessel ratios Lambda_l
//     (libbake/core/vmf_lobe.h), not Eq. (7.19)'s exp(-l^2 / (2 kappa));
//   specular, per light: sum_j alpha_j S_j (lobe_specular.h): where lobe j is narrow against the view's and the
//     light's horizons, f_s(l, v; n = mu_j, alpha_j') (n . l), the renderer's microfacet lobe around mu_j with
//     alpha_j' = min(sqrt(alpha^2 + 2 / kappa_j), kMaxFilteredAlpha)                                   Eq. (7.21)
//     (filtered_ndf_shading.h vmf_filtered_beckmann_alpha); where it reaches a horizon (the grazing far field),
//     the reference's per-normal shading integrated over the wide lobes (deviation [Han07]: its product form is
//     2-10x off there);
//   distant lighting (order-2 SH): diffuse = albedo / pi * sum_j alpha_j max(0, sum_l A_l Lambda_l(kappa_j)
//     sum_m L_lm Y_lm(mu_j)) (Eq. (7.23), vmf_sh_lighting); specular = sum_j alpha_j times the renderer's vMF
//     lobe at mu_j's mirror direction with alpha_j' (deviation [Han07]: Eq. (7.24)'s half-vector lighting is
//     replaced by the renderer's own distant-specular approximation, which every mode uses, widened per lobe).
//
// Roughness convention: the renderer's microfacet alpha (microfacet_brdf.h); a lobe of concentration kappa
// spreads each angular component by variance 1 / kappa, which adds 2 / kappa to Beckmann's alpha^2 (slope
// variance alpha^2 / 2 per axis); the same alpha' is used for GGX (same half-width at small alpha). At level 0
// every texel holds one lobe at its normal with kappa = kappa_max and the lookup gathers them into one kappa_max
// lobe at the renormalised interpolated normal (filtered_ndf_textures.h), so the image equals plain normal mapping
// up to that lobe's 2 / kappa_max widening and the diffuse series' truncation: within 1% on gentle bumps (test:
// FilteredNdfEffects.FinestLevelEqualsPlainNormalMapping), 0.1% of the mean radiance on a bumpy map
// (FilteredNdfEffects.MagnifiedBumpyMapMatchesPlainNormalMapping).
// Reference mode: `base`.
//
// Shader port: 4 J floats from the trilinear fetch, decode (kappa by a short Newton solve or a table of A^-1),
// one microfacet evaluation per lobe and light, a few bands of Bessel ratios for the diffuse term.
#pragma once

#include "libbake/eval/effect_shaders.h"

namespace mbk {

// The highest band of the clamped-cosine expansion in the vMF diffuse term. For the sharpest (kappa_max) lobes the
// truncated series misses max(t, 0) by at most 0.0095 (of 1 at normal incidence), at the terminator t = 0 where
// the kink is (0.018 at order 16, 0.012 at 24); broader lobes smooth the kink and converge faster.
inline constexpr int kVmfDiffuseOrder = 32;

ShaderPtr vmf_effect_shader(const EffectShaderRequest& request);

}  // namespace mbk
