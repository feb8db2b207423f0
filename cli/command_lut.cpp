// `microbake lut IN -o OUT.mbk [--size N]`: bakes the standardization knots of an example normal map for
// histogram-preserving blending of glints (asset kind `lut`, libbake/glint/lut_asset.h).
#include <iomanip>
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/stage_timer.h"
#include "formats/lut_layout.h"
#include "libbake/glint/lut_asset.h"

namespace mbk::cli {
namespace {

class LutCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    add_normal_map_input(app, options_.input);
    add_output_option(app, options_.output, "standardization LUT asset (.mbk)");
    app.add_option("--size", options_.size,
                   "Grid points per axis: knots of G at this many x and this many z positions per channel, plus the "
                   "example's repeated values exactly; 128 is the paper's table size")
        ->check(CLI::Range(kLutMinSize, kLutMaxSize))
        ->default_val(kLutDefaultSize);
    add_run_options(app, options_.run);
  }

  void check() override { check_asset_bake(options_.input, options_.output); }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    StageTimer timer;
    const LoadedNormalMap input = load_normal_map(options_.input.path, options_.input.load_options());
    const double load_seconds = timer.lap();
    const BakedLut lut = bake_standardization_lut(input.map, options_.size, progress);
    const AssetWriter writer = lut_asset_writer(lut, input.record);
    const double bake_seconds = timer.lap();
    options_.output.write_asset(writer);
    const double write_seconds = timer.lap();
    if (!options_.run.quiet) {
      const LutChannelStatistics &x = lut.statistics[0], &y = lut.statistics[1];
      std::cout << std::setprecision(3) << "lut: wrote " << options_.output.path << " (" << input.map.width << "x"
                << input.map.height << ", grid " << options_.size << ": " << x.knots << " + " << y.knots
                << " knots; max |G_T - G| n_x " << x.forward_error << ", n_y " << y.forward_error
                << "; max |G^-1_T - G^-1| n_x " << x.inverse_error << ", n_y " << y.inverse_error
                << "; clipped tail mass n_x " << x.clipped_tail_mass << ", n_y " << y.clipped_tail_mass;
      print_bake_times(std::cout, input.record, load_seconds, bake_seconds, write_seconds);
    }
    return 0;
  }

 private:
  struct Options {
    NormalMapInput input;
    OutputOption output;
    uint32_t size = kLutDefaultSize;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_lut_command() { return std::make_unique<LutCommand>(); }

}  // namespace mbk::cli
