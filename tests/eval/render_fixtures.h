// Shared by the evaluator tests that render scenes: baking what a scene plans (what `microbake bake` does,
// minus reporting) and rendering it filtered or as the brute-force reference.
#pragma once

#include <filesystem>

#include "libbake/core/progress.h"
#include "libbake/eval/renderer.h"
#include "libbake/scene/bake_plan.h"

namespace mbk::testing {

// Bakes every planned asset into the scene's default asset folder.
inline void bake_scene(const Scene& scene) {
  std::filesystem::create_directories(default_asset_folder(scene));
  for (const PlannedAsset& a : plan_assets(scene))
    a.recipe.bake(Progress::silent()).write(default_asset_folder(scene) / a.file_name);
}

// spp samples per pixel, or (reference > 0) the reference with reference x reference rays per pixel; `seed`
// picks the sub-pixel jitter; edge_spp > spp gives the pixels a silhouette crosses that many samples.
inline Image render(const Scene& scene, uint32_t spp, uint32_t reference = 0, uint32_t seed = 0,
                    uint32_t edge_spp = 0) {
  RenderSettings settings;
  settings.spp = spp;
  settings.reference = reference;
  settings.seed = seed;
  settings.edge_spp = edge_spp;
  return render_scene(scene, load_render_inputs(scene, settings), settings, Progress::silent());
}

}  // namespace mbk::testing
