// Per-material normal lookups: baseline MIP mapping, the `mip` effect's asset, or the reference's raw
// level 0 (see material_normals.h).
#include "libbake/eval/material_normals.h"

#include "formats/error.h"
#include "libbake/eval/mip_effect.h"
#include "libbake/scene/asset_freshness.h"
#include "libbake/scene/bake_plan.h"

namespace mbk {

Vec3 MaterialNormals::lookup(const Vec2& uv, const UvFootprint& footprint) const {
  if (filter == NormalFilter::none) return Vec3::UnitZ();
  const NormalMap& finest = pyramid->levels[0];
  const Vec3 n = filter == NormalFilter::bilinear_level0
                     ? sample_bilinear(finest, uv)
                     : sample_pyramid(*pyramid, uv, mip_lod(footprint, finest.width, finest.height));
  const double len = n.norm();
  // Means of unit vectors shorter than this have lost their direction to cancellation (and float rounding
  // of the stored levels is ~1e-7): fall back to the unperturbed normal.
  return len > 1e-6 ? Vec3(n / len) : Vec3::UnitZ();
}

namespace {

std::string scene_name(const Scene& scene) { return scene.file.empty() ? "SCENE.json" : scene.file.string(); }

// The file of a material's effect asset, after checking that it exists and matches its normal map.
std::filesystem::path effect_asset_file(const Scene& scene, const std::vector<PlannedAsset>& plan, const Material& m,
                                        const std::string& effect, const std::filesystem::path& folder) {
  const auto assets = assets_for(plan, m.name, effect);
  if (assets.size() != 1 || assets[0]->recipe->kind != "mip")
    throw Error(ExitCode::runtime_failure, "internal: effect '" + effect + "' should plan exactly one mip asset");
  const PlannedAsset& planned = *assets[0];
  const std::filesystem::path file = folder / planned.file_name;
  const std::string context = "asset of effect '" + effect + "' for material '" + m.name + "'";
  const std::string bake = "run 'microbake bake " + scene_name(scene) + "'" +
                           (folder == default_asset_folder(scene) ? "" : " --out-dir " + folder.string());
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw Error(ExitCode::io_failure, context + " is missing: " + bake, file.string());
  if (std::filesystem::exists(planned.input.path, ec)) {
    const AssetFreshness f = check_asset_freshness(planned, file, file_content_hash(planned.input.path));
    if (f.state != AssetState::up_to_date)
      throw Error(ExitCode::invalid_input, context + " is out of date (" + f.reason + "): " + bake, file.string());
  }
  return file;
}

}  // namespace

std::map<std::string, MaterialNormals> load_material_normals(const Scene& scene, NormalSource source,
                                                             const std::filesystem::path& asset_folder) {
  std::map<std::string, MaterialNormals> out;
  const std::vector<PlannedAsset> plan =
      source == NormalSource::effects ? plan_assets(scene) : std::vector<PlannedAsset>{};
  std::map<std::string, std::shared_ptr<const NormalPyramid>> loaded;  // by map file + options, or asset file
  auto cached = [&](const std::string& key, auto&& make) {
    auto it = loaded.find(key);
    if (it == loaded.end()) it = loaded.emplace(key, make()).first;
    return it->second;
  };
  for (const auto& [name, m] : scene.materials) {
    MaterialNormals normals;
    if (m.normal_map) {
      const NormalMapRef& ref = *m.normal_map;
      const std::string map_key =
          ref.path.string() + "|" + convention_name(ref.convention) + (ref.repair ? "|repair" : "|error");
      if (source == NormalSource::reference) {
        normals.filter = NormalFilter::bilinear_level0;
        normals.pyramid = cached("raw|" + map_key, [&] {
          NormalPyramid raw;
          raw.levels.push_back(load_normal_map(ref.path, ref.load_options()).map);
          return std::make_shared<const NormalPyramid>(std::move(raw));
        });
      } else if (m.effects.empty()) {
        normals.filter = NormalFilter::trilinear;
        normals.pyramid = cached("pyramid|" + map_key, [&] {
          return std::make_shared<const NormalPyramid>(
              build_normal_pyramid(load_normal_map(ref.path, ref.load_options()).map));
        });
      } else {
        for (const std::string& effect : m.effects) {
          if (effect != "mip")
            throw Error(ExitCode::runtime_failure,
                        "internal: the evaluator does not implement effect '" + effect + "'");
          normals.filter = NormalFilter::trilinear;
          const std::filesystem::path file = effect_asset_file(scene, plan, m, effect, asset_folder);
          normals.pyramid = cached("asset|" + file.string(),
                                   [&] { return std::make_shared<const NormalPyramid>(load_mip_asset(file)); });
        }
      }
    }
    out.emplace(name, std::move(normals));
  }
  return out;
}

}  // namespace mbk
