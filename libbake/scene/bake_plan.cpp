// Bake planning: dedup of asset requests and stable asset file names (see bake_plan.h).
#include "libbake/scene/bake_plan.h"

#include <cctype>
#include <cstdio>
#include <map>

#include "formats/container_layout.h"

namespace mbk {
namespace {

namespace fs = std::filesystem;

// The map's path as the scene names it, relative to the scene folder when it lies below or beside it, so
// that a scene and its maps can move together without renaming the assets.
std::string scene_relative(const Scene& scene, const fs::path& p) {
  const fs::path rel = p.lexically_relative(scene.folder.lexically_normal());
  return (rel.empty() ? p : rel).generic_string();
}

std::string file_stem_for(const fs::path& map) {
  std::string stem = map.stem().string();
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return stem.empty() ? "map" : stem;
}

std::string hex8(uint64_t v) {
  char buf[9];
  std::snprintf(buf, sizeof buf, "%08x", static_cast<unsigned>(v >> 32));
  return buf;
}

}  // namespace

std::vector<PlannedAsset> plan_assets(const Scene& scene) {
  std::vector<PlannedAsset> plan;
  std::map<std::string, size_t> index_of_request;  // dedup key -> index in plan
  for (const auto& [name, material] : scene.materials) {
    for (const std::string& effect_name : material.effects) {
      const EffectInfo* effect = find_effect(effect_name);
      for (const AssetRecipe& recipe : effect->assets) {
        const NormalMapRef& map = *material.normal_map;  // scene parsing requires a map for every effect
        std::error_code ec;
        fs::path canonical = fs::weakly_canonical(map.path, ec);
        if (ec) canonical = fs::absolute(map.path).lexically_normal();
        const nlohmann::json request = {{"kind", recipe.kind},
                                        {"parameters", recipe.parameters},
                                        {"convention", convention_name(map.convention)},
                                        {"repair", map.repair}};
        const std::string key = request.dump() + "\n" + canonical.generic_string();
        auto [it, inserted] = index_of_request.emplace(key, plan.size());
        if (inserted) {
          nlohmann::json named = request;
          named["input"] = scene_relative(scene, map.path);
          const std::string text = named.dump();
          PlannedAsset a;
          a.recipe = &recipe;
          a.input = map;
          a.file_name =
              file_stem_for(map.path) + "." + recipe.kind + "." + hex8(checksum_of(text.data(), text.size())) + ".mbk";
          plan.push_back(std::move(a));
        }
        plan[it->second].uses.push_back({name, effect_name});
      }
    }
  }
  return plan;
}

fs::path default_asset_folder(const Scene& scene) {
  const std::string stem = scene.file.empty() ? "scene" : scene.file.stem().string();
  return scene.folder / (stem + ".assets");
}

std::vector<const PlannedAsset*> assets_for(const std::vector<PlannedAsset>& plan, const std::string& material,
                                            const std::string& effect) {
  std::vector<const PlannedAsset*> out;
  for (const auto& a : plan)
    for (const auto& use : a.uses)
      if (use.material == material && use.effect == effect) out.push_back(&a);
  return out;
}

}  // namespace mbk
