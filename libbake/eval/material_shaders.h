// The shader of every material of a scene (material_shader.h): the baseline, then each effect the
// material names, in order (effect_shaders.h).
//   baseline, filtered   no normal map: (0, 0, 1); otherwise plain MIP-mapped normal mapping (material_normals.h),
//                        the pyramid read from the material's baseline `mip` asset (bake_plan.h plans it for every
//                        material with a map and an effect), or built in memory from the map for a material
//                        without effects
//   baseline, reference  the raw map's level 0, bilinear (no filtering)
// Assets: in filtered mode each effect's assets are looked up in the bake plan (libbake/scene/bake_plan.h)
// inside the asset folder; when a source is missing (assets shipped alone) by its recorded metadata
// (asset_freshness.h, find_baked_asset), so filtered rendering reads no source map. A missing asset is
// Error(io_failure) pointing at `microbake bake`; an asset that no longer matches its inputs (when they are present to
// compare) is Error(invalid_input), likewise. Maps and assets shared by several materials are loaded once
// (load_cache.h).
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "libbake/eval/effect_shaders.h"
#include "libbake/scene/scene.h"

namespace mbk {

std::map<std::string, ShaderPtr> load_material_shaders(const Scene& scene, EvalMode mode,
                                                       const std::filesystem::path& asset_folder);

}  // namespace mbk
