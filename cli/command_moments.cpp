// `microbake moments DRIVER -o OUT.mbk [--channel N]`: bakes the MIP pyramid of (f, f^2) of a grayscale or height
// image, so that the mean and variance of f over a footprint come from two lookups ([Heitz13] Sec. 4.2; asset kind
// `moments`, libbake/colormap/moment_pyramid.h).
#include <iomanip>
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/stage_timer.h"
#include "libbake/colormap/moment_pyramid.h"

namespace mbk::cli {
namespace {

class MomentsCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("DRIVER", options_.driver,
                   "Driver image f (grayscale or height; integer images read as [0, 1], float images as stored)")
        ->required();
    add_output_option(app, options_.output, "moment pyramid asset (.mbk)");
    app.add_option("--channel", options_.channel, "Image channel holding f (0 = the first)")->default_val(0);
    add_run_options(app, options_.run);
  }

  void check() override {
    options_.output.require_extension(".mbk");
    options_.output.check_writable();
  }

  int run() override {
    options_.run.apply();
    StageTimer timer;
    const Driver driver = load_driver(options_.driver, options_.channel);
    const double load_seconds = timer.lap();
    const MomentPyramid pyramid = build_moment_pyramid(driver);
    const AssetWriter writer = moments_asset_writer(pyramid, driver);
    const double bake_seconds = timer.lap();
    options_.output.write_asset(writer);
    const double write_seconds = timer.lap();
    if (!options_.run.quiet)
      std::cout << std::setprecision(4) << "moments: wrote " << options_.output.path << " (" << driver.width << "x"
                << driver.height << ", " << pyramid.levels.size() << " levels, channel " << options_.channel
                << ", mean " << pyramid.shift << "); load " << std::setprecision(3) << load_seconds << " s, bake "
                << bake_seconds << " s, write " << write_seconds << " s\n";
    return 0;
  }

 private:
  struct Options {
    std::string driver;
    OutputOption output;
    uint32_t channel = 0;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_moments_command() { return std::make_unique<MomentsCommand>(); }

}  // namespace mbk::cli
