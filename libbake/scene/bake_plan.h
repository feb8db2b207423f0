// Planning what to bake for a scene: every (material, effect) pair asks the effect registry for its
// assets; identical requests (same kind, parameters and input files, and for normal-map inputs the same
// convention and repair policy) are merged, so an asset shared by several materials is baked and loaded
// once. Each planned asset gets a stable file name inside the asset folder, `<first input's stem>.<kind>.
// <8 hex>.mbk`, where the hex digits hash the request (kind, parameters, the inputs' paths relative to the
// scene folder, conventions, repair): the same scene always names the same files, and different requests
// never share one.
//
// The asset folder defaults to `<scene folder>/<scene stem>.assets/` (scenes/demo.json ->
// scenes/demo.assets/); `bake --out-dir` and `render --assets` override it, and must then agree.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "libbake/scene/effect_registry.h"
#include "libbake/scene/scene.h"

namespace mbk {

struct AssetUse {
  std::string material, effect;
};

struct PlannedAsset {
  AssetRecipe recipe;
  std::string file_name;
  std::vector<AssetUse> uses;  // in material-name order, then effect order
};

// In order of first use (materials by name, then their effects in order, then each effect's assets).
std::vector<PlannedAsset> plan_assets(const Scene& scene);

std::filesystem::path default_asset_folder(const Scene& scene);

// The planned assets a material's effect uses (each names its recipe, hence its kind).
std::vector<const PlannedAsset*> assets_for(const std::vector<PlannedAsset>& plan, const std::string& material,
                                            const std::string& effect);

}  // namespace mbk
