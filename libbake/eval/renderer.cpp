// The evaluator's pixel loop (see renderer.h).
#include "libbake/eval/renderer.h"

#include <cmath>
#include <vector>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/eval/camera_rays.h"
#include "libbake/eval/pixel_samples.h"
#include "libbake/eval/sample_parts.h"
#include "libbake/eval/silhouette_pixels.h"
#include "libbake/eval/surface_frame.h"
#include "libbake/scene/bake_plan.h"

namespace mbk {
namespace {

// What shading needs per shape, resolved once instead of per sample.
struct ShapeShading {
  Brdf brdf;
  const MaterialShader* shader;
};

Vec3 shade_hit(const std::vector<ShapeShading>& shading, const SceneLighting& lighting, const RayDifferential& r,
               const SurfaceHit& hit, const UvFootprint& footprint) {
  const ShapeShading& s = shading[hit.shape];
  const Vec3 to_viewer = -r.ray.direction;
  const ShadingContext context{hit.p, hit.uv, footprint, surface_frame(hit, to_viewer), to_viewer, &lighting};
  return s.shader->radiance(context, s.brdf);
}

UvFootprint footprint_of(const Scene& scene, const std::vector<ShapeShading>& shading, const RayDifferential& r,
                         const SurfaceHit& hit, int max_probes) {
  UvFootprint footprint =
      uv_footprint(hit, r, shading[hit.shape].shader->uses_normal_steps() ? &scene.shapes[hit.shape] : nullptr);
  footprint.max_probes = max_probes;
  return footprint;
}

// The radiance of one sample: the ray through film point `film` with its differentials scaled to the sample's
// `step` (pixels), its footprint shaded whole or in up to max_parts parts (sample_parts.h). Reference rays: step
// (1, 1), one probe, one part.
Vec3 sample_radiance(const Scene& scene, const std::vector<ShapeShading>& shading, const SceneLighting& lighting,
                     const PinholeCamera& camera, const Vec2& film, const Vec2& step, int max_probes, int max_parts) {
  RayDifferential r = camera.ray(film.x(), film.y());
  r.ddx *= step.x();
  r.ddy *= step.y();
  const auto hit = intersect_scene(scene.shapes, r.ray);
  if (!hit) return background(lighting, r.ray.direction);
  const UvFootprint footprint = footprint_of(scene, shading, r, *hit, max_probes);
  const SampleParts parts = sample_parts(footprint.dp_dx, footprint.dp_dy, max_parts);
  if (parts.count == 1) return shade_hit(shading, lighting, r, *hit, footprint);
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < parts.count; ++k) {
    const Vec2 offset = part_offset(parts, k).cwiseProduct(step);
    RayDifferential part = camera.ray(film.x() + offset.x(), film.y() + offset.y());
    part.ddx = r.ddx, part.ddy = r.ddy;
    shrink_to_part(parts, part.ddx, part.ddy);
    const auto part_hit = intersect_scene(scene.shapes, part.ray);
    sum += part_hit ? shade_hit(shading, lighting, part, *part_hit,
                                footprint_of(scene, shading, part, *part_hit, max_probes))
                    : background(lighting, part.ray.direction);
  }
  return sum / parts.count;
}

}  // namespace

RenderInputs load_render_inputs(const Scene& scene, const RenderSettings& settings) {
  RenderInputs inputs;
  inputs.lighting = load_scene_lighting(scene);
  const auto folder = settings.asset_folder.empty() ? default_asset_folder(scene) : settings.asset_folder;
  inputs.shaders =
      load_material_shaders(scene, settings.reference > 0 ? EvalMode::reference : EvalMode::filtered, folder);
  return inputs;
}

Image render_scene(const Scene& scene, const RenderInputs& inputs, const RenderSettings& settings, Progress& progress) {
  const PinholeCamera camera(scene.camera);
  const SampleGrid grid =
      settings.reference > 0 ? SampleGrid{settings.reference, settings.reference} : sample_grid(settings.spp);
  if (grid.count() == 0) throw Error(ExitCode::bad_command_line, "samples per pixel must be at least 1");
  std::vector<ShapeShading> shading;
  for (const Shape& shape : scene.shapes) {
    const auto it = inputs.shaders.find(shape.material);
    if (it == inputs.shaders.end())
      throw Error(ExitCode::runtime_failure, "internal: no shader for material '" + shape.material + "'");
    shading.push_back({Brdf::of(scene.materials.at(shape.material)), it->second.get()});
  }
  Image image;
  image.width = camera.width();
  image.height = camera.height();
  image.channels = 3;
  image.pixels.assign(size_t(image.width) * image.height * 3, 0.0f);
  progress.start(settings.reference > 0 ? "reference" : "render", image.height);
  // Edge-adaptive sampling (silhouette_pixels.h): pixels a silhouette crosses take edge_spp samples.
  const bool edges = settings.edge_sampling();
  const std::vector<uint8_t> edge = edges ? silhouette_pixels(scene, camera) : std::vector<uint8_t>();
  const SampleGrid edge_grid = edges ? sample_grid(settings.edge_spp) : grid;
  parallel_for(0, image.height, [&](int64_t row) {
    const uint32_t y = uint32_t(row);
    for (uint32_t x = 0; x < image.width; ++x) {
      Vec3 sum = Vec3::Zero();
      const SampleGrid& pixel_grid = edges && edge[size_t(y) * image.width + x] ? edge_grid : grid;
      for (uint32_t s = 0; s < pixel_grid.count(); ++s) {
        if (settings.reference > 0) {
          const Vec2 o = sample_offset(x, y, s, grid, settings.seed);
          sum += sample_radiance(scene, shading, inputs.lighting, camera, Vec2(x + o.x(), y + o.y()), Vec2(1.0, 1.0), 1,
                                 1);
        } else {  // the cell's centre with the cell's footprint (see renderer.h)
          const Vec2 o = cell_centre(s, pixel_grid);
          sum += sample_radiance(scene, shading, inputs.lighting, camera, Vec2(x + o.x(), y + o.y()),
                                 Vec2(1.0 / pixel_grid.cols, 1.0 / pixel_grid.rows), settings.max_probes,
                                 settings.max_parts);
        }
      }
      const Vec3 pixel = sum / double(pixel_grid.count());
      for (uint32_t c = 0; c < 3; ++c) image.at(x, y, c) = float(pixel[c]);
    }
    progress.advance();
  });
  progress.finish();
  // A float image cannot hold radiance past ~3.4e38: refuse to write Inf/NaN pixels (e.g. from absurd light
  // intensities) rather than hand a renderer or `compare` an image it cannot use.
  uint64_t bad = 0;
  size_t first = 0;
  for (size_t i = 0; i < image.pixels.size(); ++i)
    if (!std::isfinite(image.pixels[i]) && bad++ == 0) first = i / 3;
  if (bad)
    throw Error(ExitCode::runtime_failure,
                "rendering produced " + std::to_string(bad) + " non-finite pixel values (overflow?), first at pixel (" +
                    std::to_string(first % image.width) + ", " + std::to_string(first / image.width) + ")");
  return image;
}

}  // namespace mbk
