// A plane receding to the horizon for render tests of far-field filtering (footprints from a few texels to
// thousands along the view): one material "m" with the given effect on map.exr in the scene's folder, a glossy GGX
// lobe, a point light, a directional light from beyond the horizon (its glare) and a sky; and a render of it with
// its assets baked first (none for a reference).
#pragma once

#include <filesystem>

#include "libbake/eval/renderer.h"
#include "libbake/scene/bake_plan.h"
#include "tests/scene/scene_test_fixtures.h"

namespace mbk::test {

inline nlohmann::json receding_plane_scene(const nlohmann::json& effect, double uv_scale) {
  return {
      {"camera",
       {{"position", {0.0, 0.4, 0.0}}, {"look_at", {0.0, 0.25, -8.0}}, {"fov_y", 24}, {"width", 64}, {"height", 40}}},
      {"shapes",
       {{{"type", "plane"},
         {"center", {0.0, 0.0, -50.0}},
         {"size", {100.0, 100.0}},
         {"uv_scale", {uv_scale, uv_scale}},
         {"material", "m"}}}},
      {"materials",
       {{"m",
         {{"albedo", {0.15, 0.15, 0.15}},
          {"specular", {{"distribution", "ggx"}, {"roughness", 0.15}, {"f0", 0.6}}},
          {"normal_map", {{"path", "map.exr"}}},
          {"effects", {effect}}}}}},
      {"lights",
       {{{"type", "point"}, {"position", {0.5, 1.5, -6.0}}, {"intensity", {2.5, 2.5, 2.5}}},
        {{"type", "directional"}, {"direction", {0.1, -0.25, 1.0}}, {"irradiance", {0.3, 0.3, 0.3}}},
        {{"type", "sky"}, {"radiance", {0.04, 0.05, 0.07}}}}}};
}

// The scene written to folder/s.json and rendered: `reference` > 0 as --reference N, else at 4 spp with its assets
// baked into the scene's default asset folder and long footprints in up to max_parts parts.
inline Image render_in(const std::filesystem::path& folder, const nlohmann::json& scene_json, uint32_t reference,
                       int max_parts = RenderSettings{}.max_parts) {
  testing::write_json(folder / "s.json", scene_json);
  const Scene scene = load_scene(folder / "s.json");
  std::filesystem::create_directories(default_asset_folder(scene));
  if (reference == 0)
    for (const PlannedAsset& a : plan_assets(scene))
      a.recipe.bake(Progress::silent()).write(default_asset_folder(scene) / a.file_name);
  RenderSettings settings;
  settings.reference = reference;
  settings.spp = reference > 0 ? 1 : 4;
  settings.max_parts = max_parts;
  return render_scene(scene, load_render_inputs(scene, settings), settings, Progress::silent());
}

}  // namespace mbk::test
