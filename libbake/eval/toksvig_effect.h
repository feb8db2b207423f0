// The evaluator side of the `toksvig` effect (libbake/scene/effect_toksvig.cpp): plain MIP-mapped normal mapping
// from the baked `mip` asset, with the specular lobe widened by the spread the mean normal's length reveals
// ([Toksvig05]; filtered_ndf_shading.h toksvig_beckmann_alpha):
//
//   m = trilinear mean normal at the footprint's LOD (unnormalised, as material_normals.h samples it), except
//       that below LOD 1 the level-0 part is the renormalised bilinear normal (interpolating between unequal
//       normals is no spread: the reference shades the interpolated normal), so LOD 0 is plain normal mapping,
//   sigma^2 = (1 - |m|) / |m|,   alpha' = min(sqrt(alpha^2 + 2 sigma^2), kMaxFilteredAlpha),
//
// then the renderer's BRDF at n = m / |m| with roughness alpha' for every light (point, directional, and the
// distant lighting's specular lobe), except where the spread reaches the view's or the light's horizon (the grazing
// far field): there the specular of a point or directional light is that of the vMF lobe of the same spread
// (kappa = 1 / sigma^2) integrated over its normals (lobe_specular.h). Roughness convention: the renderer's microfacet
// alpha (microfacet_brdf.h), widened in Beckmann's slope variance (alpha^2 / 2 per axis) and applied as is to GGX's
// alpha (same half-width at small alpha). The diffuse term is plain Lambert at n, as in Toksvig's paper. Reference
// mode: `base`.
//
// Shader port: sample the mip texture without normalising (renormalise the level-0 tap below LOD 1), len = length(m),
// widen alpha, normalise.
#pragma once

#include "libbake/eval/effect_shaders.h"

namespace mbk {

ShaderPtr toksvig_effect_shader(const EffectShaderRequest& request);

}  // namespace mbk
