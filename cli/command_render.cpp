// `microbake render SCENE -o OUT.{exr,png} [--spp N] [--edge-spp N] [--max-probes N] [--max-parts N] [--reference N]
// [--seed S] [--assets DIR]`:
// the reference shader evaluator (libbake/eval/renderer.h). EXR output is linear radiance, PNG is tone-mapped for
// viewing (libbake/eval/render_output.h). Effects read their baked assets from the asset folder (default
// <scene folder>/<scene stem>.assets, as `bake` writes it); --reference needs no assets. Prints one line, or with
// --format json one object with the stage times (schema "microbake.render/1", formats/schema/render.schema.json).
#include <cstdio>
#include <iostream>
#include <string>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/parameter_options.h"
#include "cli/stage_timer.h"
#include "formats/error.h"
#include "libbake/eval/render_output.h"
#include "libbake/eval/renderer.h"
#include "libbake/eval/sample_parts.h"
#include "libbake/scene/bake_plan.h"

namespace mbk::cli {
namespace {

class RenderCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("SCENE", options_.scene, "Scene file (JSON)")->required();
    add_output_option(app, options_.output, "rendered image (.exr: linear float; .png: clamped, sRGB-encoded 8-bit)");
    spp_option_ = add_parameter_option(
        app, integer_option("--spp", 1, 65536, 1, "Samples per pixel, stratified (render mode)"), options_.spp);
    edge_spp_option_ = add_parameter_option(
        app,
        integer_option("--edge-spp", 0, 65536, 0,
                       "Samples per pixel where a silhouette crosses the pixel (its corners see different shapes or "
                       "the background), when more than --spp; 0 = off (render mode)"),
        options_.edge_spp);
    add_parameter_option(app,
                         integer_option("--reference", 1, 256, nullptr,
                                        "Ground truth instead: N x N sub-pixel rays per pixel with unfiltered normals "
                                        "from the raw maps (no assets)"),
                         options_.reference);
    add_parameter_option(app,
                         integer_option("--seed", 0, 4294967295.0, 0,
                                        "Seed of the reference's sub-pixel jitter: two references with different seeds "
                                        "measure its own noise floor (render mode samples each cell's centre)"),
                         options_.seed);
    add_parameter_option(app,
                         integer_option("--max-probes", 1, kMaxFootprintProbes, options_.max_probes,
                                        "Anisotropic filtering: at most this many probes along a footprint's major "
                                        "axis per filtered lookup (render mode; 1 = isotropic)"),
                         options_.max_probes);
    add_parameter_option(app,
                         integer_option("--max-parts", 1, kMaxSampleParts, options_.max_parts,
                                        "Grazing footprints: a sample whose footprint is more than 8 times longer than "
                                        "wide is shaded in up to this many parts along it (render mode; 1 = whole)"),
                         options_.max_parts);
    app.add_option("--assets", options_.assets,
                   "Folder of baked assets (default: <scene folder>/<scene stem>.assets, as 'bake' writes)")
        ->type_name("DIR");
    add_format_option(app, options_.format);
    add_run_options(app, options_.run);
  }

  void check() override {
    if (!is_render_extension(options_.output.path))
      throw Error(ExitCode::bad_command_line, "the output must end in .exr or .png", options_.output.path);
    if (options_.reference > 0 && spp_option_->count() > 0)
      throw Error(ExitCode::bad_command_line,
                  "--spp and --reference exclude each other: the reference takes N x N samples per pixel");
    if (options_.reference > 0 && edge_spp_option_->count() > 0)
      throw Error(ExitCode::bad_command_line,
                  "--edge-spp and --reference exclude each other: the reference takes N x N samples in every pixel");
    options_.output.check_writable();
  }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    StageTimer timer;
    const Scene scene = load_scene(options_.scene);
    RenderSettings settings;
    settings.spp = options_.spp;
    settings.edge_spp = options_.edge_spp;
    settings.reference = options_.reference;
    settings.seed = options_.seed;
    settings.max_probes = options_.max_probes;
    settings.max_parts = options_.max_parts;
    settings.asset_folder =
        options_.assets.empty() ? default_asset_folder(scene) : std::filesystem::path(options_.assets);
    const RenderInputs inputs = load_render_inputs(scene, settings);
    const double load_seconds = timer.lap();
    const Image image = render_scene(scene, inputs, settings, progress);
    const double render_seconds = timer.lap();
    options_.output.write_with(
        [&](const std::filesystem::path& temporary) { save_render(temporary, image, options_.output.path); });
    const double write_seconds = timer.lap();
    const uint32_t samples = settings.reference > 0 ? settings.reference * settings.reference : settings.spp;
    const char* mode = settings.reference > 0 ? "reference" : "effects";
    if (options_.format == OutputFormat::json) {
      const nlohmann::json report = {
          {"schema", "microbake.render/1"},
          {"scene", options_.scene},
          {"output", options_.output.path},
          {"output_bytes", std::filesystem::file_size(options_.output.path)},
          {"width", image.width},
          {"height", image.height},
          {"mode", mode},
          {"samples_per_pixel", samples},
          {"seed", settings.seed},
          {"max_probes", settings.max_probes},
          {"max_parts", settings.max_parts},
          {"edge_spp", settings.edge_spp},
          {"asset_folder", settings.reference > 0 ? nlohmann::json() : nlohmann::json(settings.asset_folder.string())},
          {"seconds", {{"load", load_seconds}, {"render", render_seconds}, {"write", write_seconds}}}};
      std::cout << report.dump(2) << "\n";
    } else if (!options_.run.quiet) {
      const std::string at_silhouettes =
          settings.edge_sampling() ? ", " + std::to_string(settings.edge_spp) + " at silhouettes" : "";
      std::printf("rendered %s: %ux%u, %s, %u sample%s per pixel%s, %.2f s\n", options_.output.path.c_str(),
                  image.width, image.height, settings.reference > 0 ? "reference (unfiltered normals)" : "effects",
                  samples, samples == 1 ? "" : "s", at_silhouettes.c_str(),
                  load_seconds + render_seconds + write_seconds);
    }
    return 0;
  }

 private:
  struct Options {
    std::string scene;
    OutputOption output;
    uint32_t spp = 1;
    uint32_t edge_spp = 0;
    uint32_t reference = 0;
    int max_probes = UvFootprint{}.max_probes;
    int max_parts = RenderSettings{}.max_parts;
    uint32_t seed = 0;
    std::string assets;
    OutputFormat format = OutputFormat::text;
    RunOptions run;
  } options_;
  CLI::Option* spp_option_ = nullptr;
  CLI::Option* edge_spp_option_ = nullptr;
};

}  // namespace

std::unique_ptr<Command> make_render_command() { return std::make_unique<RenderCommand>(); }

}  // namespace mbk::cli
