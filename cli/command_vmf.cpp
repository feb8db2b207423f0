// `microbake vmf IN -o OUT.mbk [--lobes J] [--align C] [--material IMG] [--tolerance T] [--max-iterations N]`:
// bakes vMF mixture MIP maps of a normal map (asset kind `vmf`, libbake/filter/vmf_asset.h; [Han07] Sec. 7.6).
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/stage_timer.h"
#include "formats/error.h"
#include "libbake/filter/vmf_asset.h"
#include "libbake/image/image_io.h"

namespace mbk::cli {
namespace {

class VmfCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    add_normal_map_input(app, options_.input);
    add_output_option(app, options_.output, "vMF mixture asset (.mbk)");
    app.add_option("--lobes", options_.bake.lobes, "vMF lobes per texel (J)")
        ->check(CLI::Range(1, kVmfMaxLobes))
        ->default_val(kVmfDefaultLobes);
    app.add_option("--align", options_.bake.em.align,
                   "Coherence weight C of [Han07] Eq. 7.26 (0: lobes are only ordered to match their neighbours)")
        ->check(finite_number(0.0, 1e6))
        ->default_val(0.0);
    app.add_option("--material", options_.material,
                   "Colour/material image of the map's size (1-4 channels) averaged per lobe ([Han07] Eq. 7.25)");
    app.add_option("--tolerance", options_.bake.em.tolerance,
                   "EM stops when the mean log-likelihood per normal rises by less than this")
        ->check(finite_number(1e-15, 1.0))
        ->default_val(1e-6);
    app.add_option("--max-iterations", options_.bake.em.max_iterations, "EM iterations at most per texel and start")
        ->check(CLI::Range(1, 100000))
        ->default_val(kVmfDefaultMaxIterations);
    add_run_options(app, options_.run);
  }

  void check() override { check_asset_bake(options_.input, options_.output); }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    StageTimer timer;
    const LoadedNormalMap input = load_normal_map(options_.input.path, options_.input.load_options());
    std::optional<Image> material;
    nlohmann::json material_record;
    if (!options_.material.empty()) {
      ImageFileInfo info;
      material = load_image(options_.material, &info);
      if (material->channels > 4)
        throw Error(ExitCode::invalid_input,
                    "material image has " + std::to_string(material->channels) + " channels (at most 4)",
                    options_.material);
      material_record = {{"path", options_.material},
                         {"content_hash", file_content_hash(options_.material)},
                         {"bytes", std::filesystem::file_size(options_.material)},
                         {"width", material->width},
                         {"height", material->height},
                         {"channels", material->channels},
                         {"pixel_format", info.pixel_format},
                         {"role", "material"}};
    }
    const double load_seconds = timer.lap();
    const VmfPyramid pyramid = build_vmf_pyramid(input.map, material ? &*material : nullptr, options_.bake, progress);
    const AssetWriter writer = vmf_asset_writer(input, material ? &material_record : nullptr, pyramid, options_.bake);
    const double bake_seconds = timer.lap();
    options_.output.write_asset(writer);
    const double write_seconds = timer.lap();
    if (!options_.run.quiet) {
      double iterations = 0.0;
      for (size_t k = 1; k < pyramid.levels.size(); ++k) iterations += pyramid.levels[k].statistics.mean_iterations;
      std::cout << std::setprecision(3) << "vmf: wrote " << options_.output.path << " (" << input.map.width << "x"
                << input.map.height << ", " << pyramid.levels.size() << " levels, " << pyramid.lobes
                << " lobes per texel, align " << options_.bake.em.align;
      if (pyramid.feature_count) std::cout << ", " << pyramid.feature_count << " feature channels";
      if (pyramid.levels.size() > 1)
        std::cout << ", mean EM iterations " << iterations / double(pyramid.levels.size() - 1);
      std::cout << ", " << writer.file_size() << " bytes";
      print_bake_times(std::cout, input.record, load_seconds, bake_seconds, write_seconds);
    }
    return 0;
  }

 private:
  struct Options {
    NormalMapInput input;
    OutputOption output;
    VmfBakeOptions bake;
    std::string material;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_vmf_command() { return std::make_unique<VmfCommand>(); }

}  // namespace mbk::cli
