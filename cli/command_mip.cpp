// `microbake mip IN -o OUT.mbk`: bakes the MIP pyramid of a normal map (asset kind `mip`,
// libbake/image/mip_asset.h), the plain-filtering baseline the other techniques are compared with.
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "formats/mip_levels.h"
#include "libbake/image/mip_asset.h"

namespace mbk::cli {
namespace {

class MipCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    add_normal_map_input(app, options_.input);
    add_output_option(app, options_.output, "MIP pyramid asset (.mbk)");
    add_run_options(app, options_.run);
  }

  void check() override { check_asset_bake(options_.input, options_.output); }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    progress.start("mip (load, bake, write)", 3);
    const LoadedNormalMap input = load_normal_map(options_.input.path, options_.input.load_options());
    progress.advance();
    const AssetWriter writer = bake_mip_asset(input);
    progress.advance();
    options_.output.write_asset(writer);
    progress.finish();
    if (!options_.run.quiet) {
      std::cout << "mip: wrote " << options_.output.path << " (" << input.map.width << "x" << input.map.height << ", "
                << mip_level_sizes(input.map.width, input.map.height).size() << " levels";
      const uint64_t repaired = input.record.repaired_texels;
      if (repaired) std::cout << ", " << repaired << " invalid texel" << (repaired == 1 ? "" : "s") << " repaired";
      std::cout << ")\n";
    }
    return 0;
  }

 private:
  struct Options {
    NormalMapInput input;
    OutputOption output;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_mip_command() { return std::make_unique<MipCommand>(); }

}  // namespace mbk::cli
