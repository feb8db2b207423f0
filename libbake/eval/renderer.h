// The reference shader evaluator's main loop: for every pixel, stratified sub-pixel rays (pixel_samples.h)
// from the pinhole camera with their ray differentials (camera_rays.h) are cast at the shapes
// (shape_intersection.h); at each hit the material's shader (material_shaders.h) shades the point for the
// pixel's uv footprint (uv_footprint.h) in the tangent frame (surface_frame.h) under the scene's lights
// (scene_lighting.h); the pixel is the mean of its samples (a box filter).
//
// Two modes share every line of this loop and differ only in how shaders are built and how many rays a
// pixel gets:
//   render      `spp` rays per pixel, one through the centre of each cell of the stratified grid, each
//               carrying that cell's footprint (its differentials divided by the grid's columns and rows):
//               the cells tile the pixel, so the effects filter exactly the box the reference averages.
//               (A pixel-sized footprint per sample, as a rasteriser's derivatives are, filters the pixel
//               convolved with itself: twice as wide; a jittered position moves the box off the pixel.) Each
//               filtered lookup covers its footprint with up to `max_probes` anisotropic probes
//               (uv_footprint.h), and a footprint much longer than wide is shaded in up to `max_parts` parts
//               along its length (sample_parts.h). With `edge_spp` > spp, the pixels a silhouette crosses
//               (their corners see different shapes, silhouette_pixels.h) take edge_spp samples instead: filtering
//               covers texture, not coverage;
//   reference   N x N rays per pixel, every effect's ground truth unfiltered (the baseline: bilinear in the
//               raw map's level 0): the brute-force image every technique is compared with. No assets are
//               read.
// Pixels are written independently (parallel_for over rows), so the image does not depend on --threads.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "libbake/core/progress.h"
#include "libbake/eval/material_shaders.h"
#include "libbake/eval/scene_lighting.h"
#include "libbake/eval/uv_footprint.h"
#include "libbake/image/image_io.h"
#include "libbake/scene/scene.h"

namespace mbk {

struct RenderSettings {
  uint32_t spp = 1;        // samples per pixel (render mode)
  uint32_t reference = 0;  // > 0: reference mode with reference x reference samples per pixel
  uint32_t seed = 0;       // reference mode's sub-pixel jitter seed (pixel_samples.h); 0 is the default
  int max_probes = UvFootprint{}.max_probes;  // render mode: anisotropic probes per filtered lookup
  int max_parts = 4;                          // render mode: parts a long footprint is shaded in (sample_parts.h)
  uint32_t edge_spp = 0;  // render mode: samples of the pixels a silhouette crosses, when more than spp (0: off)
  std::filesystem::path asset_folder;  // where effects' assets are; empty: default_asset_folder(scene)

  // Whether the pixels a silhouette crosses take edge_spp samples (render mode, edge_spp more than spp).
  bool edge_sampling() const { return reference == 0 && edge_spp > spp; }
};

// What a render reads from disk: projected distant lighting and each material's shader.
struct RenderInputs {
  SceneLighting lighting;
  std::map<std::string, ShaderPtr> shaders;
};

RenderInputs load_render_inputs(const Scene& scene, const RenderSettings& settings);

// Linear RGB, 3 channels, camera width x height. Reports one progress unit per row.
Image render_scene(const Scene& scene, const RenderInputs& inputs, const RenderSettings& settings, Progress& progress);

}  // namespace mbk
