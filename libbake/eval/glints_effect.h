// The evaluator side of the `glints` effect (libbake/scene/effect_glints.cpp; [Wang20], libbake/glint/): the
// specular of point and directional lights comes from the P-NDF of the infinite microstructure over the
// pixel's footprint; everything else (diffuse, and the distant lighting's specular with the material's base
// roughness) is shaded around the macro-surface normal, as the issue asks ("the scene's base roughness for
// everything else"). Per light, with the tangent frame of the hit (x = +u, y = +v, z = the macro normal):
//
//   f_s(l, v) = F(v . h) G2(l, v) D(h_x, h_y) / (4 (n . l)(n . v))      (microfacet_brdf.h, D replaced)
//
// G2 and F are the material's (its base roughness and f0). D by mode:
//   filtered   D_P(h_x, h_y) over the pixel's footprint (glint_surface_mapping.h: uv -> target plane, with the
//              v flip; footprint sigma = the pixel's longer uv axis in texels / sqrt(12)), by the implicit-hierarchy
//              traversal over the baked `lut` and `rmq` assets (glint_surface.h).
//   reference  the exact point's NDF (glint_pndf.h point_ndf: the intrinsic-roughness Gaussian around the
//              blended normal n(u) at the ray's exact uv), brute force over the infinite microstructure: the
//              pixel is resolved by the reference's many rays. It reads no assets, so for `histogram` it
//              standardizes the example itself (65536-sample tables, round trip ~1e-5).
// Shader port: the point query, the range query and the traversal are libbake/glint/blended_normal.cpp,
// blended_range.cpp and glint_pndf.cpp (a few hundred lines, no allocation on the traversal path).
#pragma once

#include "libbake/eval/effect_shaders.h"

namespace mbk {

ShaderPtr glints_effect_shader(const EffectShaderRequest& request);

}  // namespace mbk
