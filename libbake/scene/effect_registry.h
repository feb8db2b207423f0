// The registry of effects a material can name in its `effects` list. Each effect declares:
//   - its scene options: `parameters` declares every key an effect object may hold besides "name" (the technique
//     parameters it bakes with, technique_parameters.h, and its own); the scene reads them with read_parameter
//     unless the effect has a parse_options of its own (keys that depend on each other, files to resolve), which
//     must read exactly the declared keys (tests/scene/parameter_schema_test.cpp checks it);
//   - whether it needs the material's normal map;
//   - the assets it needs baked for one material (assets): per asset, the kind (formats/asset_kind.h),
//     the canonical bake parameters and the input files, which `bake` compares with a file's metadata to
//     decide whether it is up to date (asset_freshness.h), and the function that bakes it.
// An effect lives in libbake/scene/effect_<name>.cpp (its `<name>_effect()`), listed once in
// effect_registry.cpp; its evaluator side is registered in libbake/eval/effect_shaders.cpp.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/asset_writer.h"
#include "libbake/core/progress.h"
#include "libbake/scene/effect_use.h"
#include "libbake/scene/json_fields.h"
#include "libbake/scene/parameter_schema.h"
#include "libbake/scene/scene.h"

namespace mbk {

// A file an asset is baked from.
struct BakeInput {
  std::filesystem::path path;              // resolved
  std::optional<NormalMapRef> normal_map;  // set when read as a normal map: convention and policy matter too
  std::string option;                      // how `microbake <kind>` takes it: "" the positional INPUT, or "--curves"
};

struct AssetRecipe {
  std::string kind;                            // an asset kind name
  nlohmann::json parameters;                   // canonical bake parameters (an object; {} without knobs)
  std::vector<BakeInput> inputs;               // recorded in the asset's "inputs", in this order
  std::function<AssetWriter(Progress&)> bake;  // reads `inputs` and bakes; throws Error
  // The values of the technique's parameters (technique_schema(kind)) that make `microbake <kind>` bake the same
  // bytes; a parameter absent here takes its default (cli/asset_command.h turns them into options).
  nlohmann::json technique_values = nlohmann::json::object();
  std::string technique = {};  // the command (technique) that bakes it, when its name is not the kind's
};

struct EffectInfo {
  std::string name;
  std::string summary;
  bool needs_normal_map = true;
  // Whether it colours the material (the colour-map effects): those come last in a material's list, since the
  // effects that supply normals or reflect light (mip, crease, glints) build their shader afresh and would drop a
  // colour set before them; consecutive colour effects combine (libbake/eval/colormap_effect.h).
  bool sets_albedo = false;
  std::vector<Parameter> parameters;  // the keys of the effect's object; empty: it is named as a string only
  // Reads the effect's keys into canonical options; nullptr: each of `parameters` by read_parameter.
  std::function<EffectUse(JsonObjectReader& options, const std::filesystem::path& scene_folder)> parse_options;
  std::function<std::vector<AssetRecipe>(const Material&, const EffectUse&)> assets;
};

std::span<const EffectInfo> effect_registry();
const EffectInfo* find_effect(std::string_view name);
// "mip, ..." for error messages.
std::string known_effect_names();

// The normal map of a material as a bake input (for effects that bake from it).
BakeInput normal_map_input(const Material& material);
// The `mip` asset of a material's normal map (effect_mip.cpp; used by the `mip` and `toksvig` effects).
AssetRecipe mip_asset_recipe(const Material& material);

// A required file option `key` of an effect: its path as written (returned, for the canonical options) and,
// resolved against the scene folder, in use.files[key]. Error(invalid_input) at the option's JSON path when
// it is not a non-empty string.
std::string effect_file_option(JsonObjectReader& r, const std::string& key, const std::filesystem::path& folder,
                               EffectUse& use);

// The effects, one file each.
EffectInfo mip_effect();
EffectInfo glints_effect();
EffectInfo histogram_effect();  // effect_histogram.cpp
EffectInfo sh_effect();
EffectInfo vmf_effect();
EffectInfo toksvig_effect();
EffectInfo colormap_effect();         // effect_colormap.cpp
EffectInfo colormap_height_effect();  // effect_colormap.cpp
EffectInfo colormap_slope_effect();   // effect_colormap.cpp
EffectInfo crease_effect();

}  // namespace mbk
