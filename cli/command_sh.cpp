// `microbake sh IN -o OUT.mbk [--order L] [--precision f16|f32] [--window none|hann|lanczos]`: bakes the SH
// NDF pyramid of a normal map (asset kind `sh`, libbake/filter/sh_asset.h; [Han07] Sec. 7.4).
#include <iomanip>
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/stage_timer.h"
#include "libbake/core/sh_basis.h"
#include "libbake/filter/sh_asset.h"

namespace mbk::cli {
namespace {

class ShCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    add_normal_map_input(app, options_.input);
    add_output_option(app, options_.output, "SH NDF pyramid asset (.mbk)");
    app.add_option("--order", options_.order,
                   "Highest SH band L ((L+1)^2 coefficients per texel); the paper shades with L ~ sqrt(4 s) for a "
                   "Blinn-Phong exponent s")
        ->check(CLI::Range(0, kMaxShOrder))
        ->default_val(kShDefaultOrder);
    app.add_option("--precision", options_.precision, "Element type of the coefficient levels")
        ->check(CLI::IsMember({"f16", "f32"}))
        ->default_val("f16");
    app.add_option("--window", options_.window,
                   "Window the evaluator applies per band against ringing (stored, not baked into the coefficients)")
        ->check(CLI::IsMember({"none", "hann", "lanczos"}))
        ->default_val("none");
    add_run_options(app, options_.run);
  }

  void check() override { check_asset_bake(options_.input, options_.output); }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    StageTimer timer;
    const LoadedNormalMap input = load_normal_map(options_.input.path, options_.input.load_options());
    const double load_seconds = timer.lap();
    const ShBakeOptions bake{options_.order, parse_precision(options_.precision), parse_window(options_.window)};
    ShPyramid pyramid = build_sh_pyramid(input.map, bake.order, progress);
    const size_t levels = pyramid.levels.size() + 1;
    const AssetWriter writer = sh_asset_writer(input, std::move(pyramid), bake);
    const double bake_seconds = timer.lap();
    options_.output.write_asset(writer);
    const double write_seconds = timer.lap();
    if (!options_.run.quiet) {
      std::cout << std::setprecision(3) << "sh: wrote " << options_.output.path << " (" << input.map.width << "x"
                << input.map.height << ", " << levels << " levels, order " << bake.order << ", " << sh_count(bake.order)
                << " " << options_.precision << " coefficients per texel, window " << options_.window << ", "
                << writer.file_size() << " bytes";
      print_bake_times(std::cout, input.record, load_seconds, bake_seconds, write_seconds);
    }
    return 0;
  }

 private:
  struct Options {
    NormalMapInput input;
    OutputOption output;
    int order = kShDefaultOrder;
    std::string precision = "f16";
    std::string window = "none";
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_sh_command() { return std::make_unique<ShCommand>(); }

}  // namespace mbk::cli
