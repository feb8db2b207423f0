// The `mip` effect: shading normals from the baked MIP pyramid (asset kind `mip`, formats/kind_mip.cpp),
// the way a renderer ships one. The asset is read through formats/ alone and sampled exactly like the
// baseline (trilinear, renormalised; material_normals.h), so the image must equal the baseline's.
//
// Shader port: upload level_k as mip level k of an RGB32F texture with repeat wrapping and trilinear
// filtering; sample at the footprint's LOD (uv_footprint.h); normalise.
#pragma once

#include <filesystem>

#include "libbake/eval/effect_shaders.h"
#include "libbake/image/normal_pyramid.h"

namespace mbk {

// Opens and checks a mip asset (kind, level count and shapes from its parameters). Error: io_failure when
// unreadable, invalid_input when it is not a well-formed mip asset.
NormalPyramid load_mip_asset(const std::filesystem::path& file);

// Filtered: a NormalMappedShader sampling the asset trilinearly. Reference: `base` (the raw map).
ShaderPtr mip_effect_shader(const EffectShaderRequest& request);

}  // namespace mbk
