// Bake planning: dedup of asset requests and content-addressed asset file names (see bake_plan.h).
#include "libbake/scene/bake_plan.h"

#include <cctype>
#include <map>

#include "formats/container_layout.h"
#include "libbake/image/normal_map.h"

namespace mbk {
namespace {

namespace fs = std::filesystem;

std::string file_stem_for(const fs::path& map) {
  std::string stem = map.stem().string();
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return stem.empty() ? "map" : stem;
}

nlohmann::json read_as(const BakeInput& in) {
  if (!in.normal_map) return nlohmann::json::object();
  return {{"convention", convention_request_name(in.normal_map->convention)}, {"repair", in.normal_map->repair}};
}

// The content hash of each input, "" for a missing file; each file is read once per plan.
class InputHashes {
 public:
  std::vector<std::string> of(const AssetRecipe& recipe) {
    std::vector<std::string> hashes;
    for (const BakeInput& in : recipe.inputs) {
      const std::string key = in.path.lexically_normal().string();
      auto it = known_.find(key);
      if (it == known_.end()) {
        std::error_code ec;
        it = known_.emplace(key, fs::is_regular_file(in.path, ec) ? file_content_hash(in.path) : "").first;
      }
      hashes.push_back(it->second);
    }
    return hashes;
  }

 private:
  std::map<std::string, std::string> known_;
};

}  // namespace

std::string asset_request_text(const AssetRecipe& recipe, const std::vector<std::string>& input_hashes) {
  nlohmann::json inputs = nlohmann::json::array();
  for (size_t i = 0; i < recipe.inputs.size(); ++i)
    inputs.push_back({{"content_hash", input_hashes.at(i)}, {"read_as", read_as(recipe.inputs[i])}});
  return nlohmann::json{{"kind", recipe.kind}, {"parameters", recipe.parameters}, {"inputs", inputs}}.dump();
}

std::string asset_name_prefix(const AssetRecipe& recipe) {
  return file_stem_for(recipe.inputs.empty() ? fs::path("asset") : recipe.inputs.front().path) + "." + recipe.kind +
         ".";
}

std::string asset_file_name(const AssetRecipe& recipe, const std::vector<std::string>& input_hashes) {
  const std::string text = asset_request_text(recipe, input_hashes);
  return asset_name_prefix(recipe) + checksum_hex(checksum_of(text.data(), text.size())) + ".mbk";
}

std::vector<PlannedAsset> plan_assets(const Scene& scene) {
  std::vector<PlannedAsset> plan;
  std::map<std::string, size_t> index_of_request;  // dedup key -> index in plan
  InputHashes hashes;
  auto add = [&](AssetRecipe recipe, const std::string& material, const std::string& effect) {
    const std::vector<std::string> input_hashes = hashes.of(recipe);
    bool complete = true;
    nlohmann::json where_missing = nlohmann::json::array();
    for (size_t i = 0; i < recipe.inputs.size(); ++i) {
      complete = complete && !input_hashes[i].empty();
      std::error_code ec;
      fs::path canonical = fs::weakly_canonical(recipe.inputs[i].path, ec);
      where_missing.push_back((ec ? fs::absolute(recipe.inputs[i].path).lexically_normal() : canonical).string());
    }
    // The same content-addressed name is the same asset; without every input, the same files read alike are.
    const std::string name = complete ? asset_file_name(recipe, input_hashes) : "";
    const std::string key = complete ? name : asset_request_text(recipe, input_hashes) + where_missing.dump();
    auto [it, inserted] = index_of_request.emplace(key, plan.size());
    if (inserted) plan.push_back({std::move(recipe), name, {}});
    plan[it->second].uses.push_back({material, effect});
  };
  for (const auto& [name, material] : scene.materials)
    for (const EffectUse& use : material.effects)
      for (AssetRecipe& recipe : find_effect(use.name)->assets(material, use)) add(std::move(recipe), name, use.name);
  for (const auto& [name, material] : scene.materials)
    if (material.normal_map && !material.effects.empty()) add(mip_asset_recipe(material), name, kBaselineUse);
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
