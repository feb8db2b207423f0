// `microbake moments INPUT -o OUT.mbk [--channel N]`: bakes the MIP pyramid of (f, f^2) of a grayscale or height
// image, so that the mean and variance of f over a footprint come from two lookups ([Heitz13] Sec. 4.2; asset kind
// `moments`, libbake/colormap/moment_pyramid.h).
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "libbake/colormap/moment_pyramid.h"

namespace mbk::cli {
namespace {

class MomentsCommand : public BakingCommand {
 public:
  MomentsCommand() : BakingCommand("moments", "moment pyramid asset (.mbk)") {}

 private:
  void add_inputs(CLI::App& app) override {
    app.add_option("INPUT", path_,
                   "Driver image f (grayscale or height; integer images read as [0, 1], float images as stored)")
        ->required();
  }

  void load() override { driver_ = load_driver(path_, channel()); }

  void bake(Progress&) override {
    pyramid_ = build_moment_pyramid(driver_);
    asset_ = moments_asset_writer(pyramid_, driver_);
  }

  std::string summary() const override {
    std::ostringstream s;
    s << std::setprecision(4) << driver_.width << "x" << driver_.height << ", " << pyramid_.levels.size()
      << " levels, channel " << channel() << ", mean " << pyramid_.shift;
    return s.str();
  }

  uint32_t channel() const { return parameters().at("channel").get<uint32_t>(); }

  std::string path_;
  Driver driver_;
  MomentPyramid pyramid_;
};

}  // namespace

std::unique_ptr<Command> make_moments_command() { return std::make_unique<MomentsCommand>(); }

}  // namespace mbk::cli
