// Building each material's shader from its baseline and its effects (see material_shaders.h).
#include "libbake/eval/material_shaders.h"

#include "formats/error.h"
#include "libbake/eval/material_normals.h"
#include "libbake/eval/mip_effect.h"
#include "libbake/scene/asset_freshness.h"
#include "libbake/scene/bake_plan.h"

namespace mbk {
namespace {

std::string scene_name(const Scene& scene) { return scene.file.empty() ? "SCENE.json" : scene.file.string(); }

// `baked_mip`: the material's baseline `mip` asset (filtered mode, when planned): the pyramid comes from it and the
// map is not read.
ShaderPtr baseline_shader(const Material& m, EvalMode mode, const std::filesystem::path& baked_mip, LoadCache& cache) {
  MaterialNormals normals;
  if (!baked_mip.empty()) {
    normals.filter = NormalFilter::trilinear;
    normals.pyramid =
        cache.get<NormalPyramid>("mip asset|" + baked_mip.string(), [&] { return load_mip_asset(baked_mip); });
  } else if (m.normal_map) {
    const NormalMapRef& ref = *m.normal_map;
    const std::string map_key =
        ref.path.string() + "|" + convention_request_name(ref.convention) + (ref.repair ? "|repair" : "|error");
    if (mode == EvalMode::reference) {
      normals.filter = NormalFilter::bilinear_level0;
      normals.pyramid = cache.get<NormalPyramid>("raw map|" + map_key, [&] {
        NormalPyramid raw;
        raw.levels.push_back(load_normal_map(ref.path, ref.load_options()).map);
        return raw;
      });
    } else {
      normals.filter = NormalFilter::trilinear;
      normals.pyramid = cache.get<NormalPyramid>("map pyramid|" + map_key, [&] {
        std::error_code ec;
        if (!std::filesystem::exists(ref.path, ec))
          throw Error(ExitCode::io_failure,
                      "normal map of material '" + m.name +
                          "' not found: a material without effects shades from its map directly (name an effect, "
                          "e.g. \"mip\", to ship the map baked)",
                      ref.path.string());
        return build_normal_pyramid(load_normal_map(ref.path, ref.load_options()).map);
      });
    }
  }
  return std::make_shared<NormalMappedShader>(
      [normals](const Vec2& uv, const UvFootprint& f) { return normals.lookup(uv, f); });
}

// The files of a material's effect assets (effect kBaselineUse: its baseline), after checking that each exists and
// matches its inputs. Without an input (assets shipped alone) the file is found by its recorded metadata.
std::vector<std::filesystem::path> effect_asset_files(const Scene& scene, const std::vector<PlannedAsset>& plan,
                                                      const Material& m, const std::string& effect,
                                                      const std::filesystem::path& folder) {
  const std::string bake = "run 'microbake bake " + scene_name(scene) + "'" +
                           (folder == default_asset_folder(scene) ? "" : " --out-dir " + folder.string());
  std::vector<std::filesystem::path> files;
  for (const PlannedAsset* planned : assets_for(plan, m.name, effect)) {
    const std::string context = planned->recipe.kind + " asset of " +
                                (effect == kBaselineUse ? "the baseline" : "effect '" + effect + "'") +
                                " for material '" + m.name + "'";
    const std::filesystem::path file = find_baked_asset(*planned, folder);
    if (file.empty()) {
      std::string missing;
      for (const BakeInput& in : planned->recipe.inputs) {
        std::error_code ec;
        if (!std::filesystem::exists(in.path, ec)) missing += (missing.empty() ? "" : ", ") + in.path.string();
      }
      throw Error(ExitCode::io_failure,
                  context + " is missing, and its source (" + missing +
                      ") is not here to name it: bake where the sources are, and ship the asset folder",
                  folder.string());
    }
    const AssetFreshness f = check_asset_freshness(*planned, file);
    if (f.state == AssetState::missing)
      throw Error(ExitCode::io_failure, context + " is missing: " + bake, file.string());
    if (f.state == AssetState::stale)
      throw Error(ExitCode::invalid_input, context + " is out of date (" + f.reason + "): " + bake, file.string());
    files.push_back(file);
  }
  return files;
}

}  // namespace

std::map<std::string, ShaderPtr> load_material_shaders(const Scene& scene, EvalMode mode,
                                                       const std::filesystem::path& asset_folder) {
  const std::vector<PlannedAsset> plan = mode == EvalMode::filtered ? plan_assets(scene) : std::vector<PlannedAsset>{};
  LoadCache cache;
  std::map<std::string, ShaderPtr> out;
  for (const auto& [name, m] : scene.materials) {
    std::filesystem::path baked_mip;
    if (mode == EvalMode::filtered)
      if (const auto files = effect_asset_files(scene, plan, m, kBaselineUse, asset_folder); !files.empty())
        baked_mip = files.front();
    ShaderPtr shader = baseline_shader(m, mode, baked_mip, cache);
    for (const EffectUse& use : m.effects) {
      const EffectShaderFactory* make = find_effect_shader(use.name);
      if (!make)
        throw Error(ExitCode::runtime_failure, "internal: the evaluator does not implement effect '" + use.name + "'");
      std::vector<std::filesystem::path> assets;
      if (mode == EvalMode::filtered) assets = effect_asset_files(scene, plan, m, use.name, asset_folder);
      shader = (*make)(EffectShaderRequest{scene, m, use, mode, std::move(assets), shader, cache});
    }
    out.emplace(name, std::move(shader));
  }
  return out;
}

}  // namespace mbk
