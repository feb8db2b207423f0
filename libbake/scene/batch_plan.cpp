// Merging the plans of several scenes (see batch_plan.h).
#include "libbake/scene/batch_plan.h"

#include <map>

namespace mbk {

std::vector<BatchAsset> plan_batch(const std::vector<BatchScene>& scenes) {
  std::vector<BatchAsset> batch;
  std::map<std::string, size_t> index_of;  // output file, or the scene-local request of an asset missing an input
  for (size_t s = 0; s < scenes.size(); ++s) {
    const BatchScene& scene = scenes[s];
    std::vector<PlannedAsset> plan = plan_assets(scene.scene);
    for (size_t i = 0; i < plan.size(); ++i) {
      PlannedAsset& planned = plan[i];
      BatchAsset asset;
      if (!planned.file_name.empty()) {
        asset.file = (scene.asset_folder / planned.file_name).lexically_normal();
      } else {
        for (const BakeInput& in : planned.recipe.inputs) {
          std::error_code ec;
          if (std::filesystem::is_regular_file(in.path, ec)) continue;
          asset.missing_input = std::string(in.normal_map ? "normal map " : "input file ") + in.path.string();
          break;
        }
      }
      const std::string key =
          asset.file.empty() ? "missing|" + std::to_string(s) + "|" + std::to_string(i) : asset.file.string();
      const std::vector<AssetUse> uses = planned.uses;
      auto [it, inserted] = index_of.emplace(key, batch.size());
      if (inserted) {
        asset.planned = std::move(planned);
        batch.push_back(std::move(asset));
      }
      for (const AssetUse& use : uses) batch[it->second].uses.push_back({scene.name, use.material, use.effect});
    }
  }
  return batch;
}

std::string use_text(const BatchUse& use) {
  return use.scene + ": material '" + use.material + "', " +
         (use.effect == kBaselineUse ? std::string("its baseline") : "effect '" + use.effect + "'");
}

std::vector<BatchScene> load_batch_scenes(const std::vector<std::string>& names, const std::filesystem::path& out_dir) {
  std::vector<BatchScene> scenes;
  for (const std::string& name : names) {
    Scene scene = load_scene(name);
    std::filesystem::path folder = out_dir.empty() ? default_asset_folder(scene) : out_dir;
    scenes.push_back({name, std::move(scene), std::move(folder)});
  }
  return scenes;
}

}  // namespace mbk
