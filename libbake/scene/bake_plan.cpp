// Bake planning: dedup of asset requests and stable asset file names (see bake_plan.h).
#include "libbake/scene/bake_plan.h"

#include <cctype>
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

}  // namespace

std::vector<PlannedAsset> plan_assets(const Scene& scene) {
  std::vector<PlannedAsset> plan;
  std::map<std::string, size_t> index_of_request;  // dedup key -> index in plan
  for (const auto& [name, material] : scene.materials) {
    for (const EffectUse& use : material.effects) {
      for (AssetRecipe& recipe : find_effect(use.name)->assets(material, use)) {
        // Two requests are the same asset when everything but where the files are written down agrees.
        nlohmann::json request = {{"kind", recipe.kind}, {"parameters", recipe.parameters}};
        nlohmann::json canonical_inputs = nlohmann::json::array(), named_inputs = nlohmann::json::array();
        for (const BakeInput& in : recipe.inputs) {
          nlohmann::json how = nlohmann::json::object();
          if (in.normal_map)
            how = {{"convention", convention_request_name(in.normal_map->convention)},
                   {"repair", in.normal_map->repair}};
          std::error_code ec;
          fs::path canonical = fs::weakly_canonical(in.path, ec);
          if (ec) canonical = fs::absolute(in.path).lexically_normal();
          canonical_inputs.push_back({{"file", canonical.generic_string()}, {"read_as", how}});
          named_inputs.push_back({{"file", scene_relative(scene, in.path)}, {"read_as", how}});
        }
        const std::string key = request.dump() + "\n" + canonical_inputs.dump();
        auto [it, inserted] = index_of_request.emplace(key, plan.size());
        if (inserted) {
          request["inputs"] = named_inputs;
          const std::string text = request.dump();
          PlannedAsset a;
          a.file_name = file_stem_for(recipe.inputs.empty() ? fs::path("asset") : recipe.inputs.front().path) + "." +
                        recipe.kind + "." + checksum_hex(checksum_of(text.data(), text.size())).substr(0, 8) + ".mbk";
          a.recipe = std::move(recipe);
          plan.push_back(std::move(a));
        }
        plan[it->second].uses.push_back({name, use.name});
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
