// The registry of effects a material can name in its `effects` list. Each effect declares the assets it
// needs baked from the material's normal map: the asset kind (formats/asset_kind.h), its canonical bake
// parameters (recorded in the asset's metadata and compared by `bake` to decide whether a file is up to
// date) and the libbake function that bakes it. A technique registers its effect with one entry in
// effect_registry() (effect_registry.cpp) and one evaluator hook in libbake/eval/material_normals.cpp.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/asset_writer.h"
#include "libbake/image/normal_map.h"

namespace mbk {

struct AssetRecipe {
  std::string kind;           // an asset kind name
  nlohmann::json parameters;  // canonical parameters (an object; {} when the bake has no knobs)
  std::function<AssetWriter(const LoadedNormalMap&)> bake;
};

struct EffectInfo {
  std::string name;
  std::string summary;
  std::vector<AssetRecipe> assets;  // baked from the material's normal map, in this order
};

std::span<const EffectInfo> effect_registry();
const EffectInfo* find_effect(std::string_view name);
// "mip, ..." for error messages.
std::string known_effect_names();

}  // namespace mbk
