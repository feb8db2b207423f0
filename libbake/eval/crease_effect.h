// The `crease` effect's shaders ([Parilov05]; the bake side is libbake/scene/effect_crease.cpp).
//   filtered   the normal reconstructed from the baked `crease` asset at the exact point (Sec. 4.3, appendix;
//              formats/crease_reconstruction.h), through Eq. (1) with the scene's profile when it names one.
//              The technique is for magnification: it ignores the footprint, and the renderer's samples per
//              pixel are all the filtering it gets (far away it aliases like unfiltered normal mapping).
//   reference  the exact crease normal from the raw map and curves (exact_crease_normals.h), no asset.
// uv maps to texel coordinates as every lookup does (texture_taps.h texel_coordinates): x = frac(u) W,
// y = frac(1 - v) H. Unlike the bilinear lookups, which wrap, the crease lattice clamps at the map's border
// (formats/crease_field.h), so a map tiled with uv_scale > 1 shows a seam where its border texels differ, and a
// curve ending at one border is not continued across the seam.
//
// Shader port: keep the asset's seven sections as textures (formats/SPEC.md "Kind 6: crease"), fetch the four
// lattice samples and the cell's signature around the point, and run reconstruct_crease + crease_normal.
#pragma once

#include "libbake/eval/effect_shaders.h"

namespace mbk {

ShaderPtr crease_effect_shader(const EffectShaderRequest& request);

}  // namespace mbk
