// Planning what to bake for a scene: every (material, effect) pair asks the effect registry for its
// assets, and every material with a normal map that names an effect also gets the `mip` asset of its map, the
// plain baseline the effects draw over (so that `render` needs no source map when everything is baked). Identical
// requests are merged, so an asset shared by several materials is baked and loaded once.
//
// Asset file names are content-addressed (docs/commands/bake.md "Asset file names"):
//   <first input's stem>.<kind>.<16 hex>.mbk
// where the hex digits are the XXH3-64 of the canonical request text
//   {"inputs":[{"content_hash":"xxh3:...","read_as":{...}}, ...],"kind":"mip","parameters":{...}}
// (nlohmann::json::dump of an object, keys sorted; read_as is {"convention": "auto"|"+Y"|"-Y", "repair": bool}
// for a normal map, {} for any other input; parameters are the recipe's canonical bake parameters). Nothing of
// the scene's folder or of how a path is spelled enters the name: `bake scene.json`, `render $PWD/scene.json` and
// `plan` agree, and the same map with the same settings names the same file in any scene. When an input file is
// missing the name cannot be computed (file_name is empty): `bake` and `plan` refuse, `render` finds the asset by
// its recorded metadata (asset_freshness.h, find_baked_asset).
//
// The asset folder defaults to `<scene folder>/<scene stem>.assets/` (scenes/demo.json ->
// scenes/demo.assets/); `bake --out-dir`, `plan --out-dir` and `render --assets` override it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "libbake/scene/effect_registry.h"
#include "libbake/scene/scene.h"

namespace mbk {

struct AssetUse {
  std::string material, effect;  // effect "baseline": the material's plain normal mapping
};

struct PlannedAsset {
  AssetRecipe recipe;
  std::string file_name;       // content-addressed; empty when an input file is missing
  std::vector<AssetUse> uses;  // effects (materials by name, then effect order), then baselines
};

// The effect name of a material's baseline use (AssetUse::effect).
inline constexpr const char* kBaselineUse = "baseline";

// In order of first use (materials by name, then their effects in order, then each effect's assets; then the
// materials' baselines). An asset's uses are in the same order.
std::vector<PlannedAsset> plan_assets(const Scene& scene);

// The canonical request text of a recipe whose inputs hash as given (see the file comment), and the file name.
std::string asset_request_text(const AssetRecipe& recipe, const std::vector<std::string>& input_hashes);
std::string asset_file_name(const AssetRecipe& recipe, const std::vector<std::string>& input_hashes);
// "<stem>.<kind>.": the part of the name that does not depend on the inputs' contents.
std::string asset_name_prefix(const AssetRecipe& recipe);

std::filesystem::path default_asset_folder(const Scene& scene);

// The planned assets a material's effect uses (each names its recipe, hence its kind); effect kBaselineUse: the
// material's baseline `mip` asset, if planned.
std::vector<const PlannedAsset*> assets_for(const std::vector<PlannedAsset>& plan, const std::string& material,
                                            const std::string& effect);

}  // namespace mbk
