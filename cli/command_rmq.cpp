// `microbake rmq IN -o OUT.mbk [--patch P] [--bits 16|8]`: bakes an example normal map's RMQ min/max table
// for glint range queries (asset kind `rmq`, libbake/glint/rmq_asset.h). Its summary line reports the wall
// time of loading, baking and writing (scripts/bench-glint-rmq.sh reads it; the asset holds no time).
#include <bit>
#include <iomanip>
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/stage_timer.h"
#include "formats/error.h"
#include "formats/rmq_layout.h"
#include "libbake/glint/rmq_asset.h"
#include "libbake/glint/rmq_table.h"

namespace mbk::cli {
namespace {

class RmqCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    add_normal_map_input(app, options_.input);
    add_output_option(app, options_.output, "RMQ table asset (.mbk)");
    app.add_option("--patch", options_.patch,
                   "Largest stored square side P in texels: a power of two in [1, 4096], not above the example's "
                   "smaller side; levels 0..log2(P) are stored. Default 64 (7 levels), or the largest power of "
                   "two that fits a smaller example")
        ->check(CLI::Validator(
            [](std::string& value) -> std::string {
              uint64_t p = 0;
              try {
                p = std::stoull(value);
              } catch (const std::exception&) {
                return "not a number";
              }
              return std::has_single_bit(p) && p <= kRmqMaxPatch ? "" : "must be a power of two in [1, 4096]";
            },
            "POWER OF TWO"));
    app.add_option("--bits", options_.bits, "Bits per stored bound: 16 (8 bytes per entry) or 8 (4 bytes)")
        ->check(CLI::IsMember({8u, 16u}))
        ->default_val(16u);
    add_run_options(app, options_.run);
  }

  void check() override { check_asset_bake(options_.input, options_.output); }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    StageTimer timer;
    const LoadedNormalMap input = load_normal_map(options_.input.path, options_.input.load_options());
    const uint32_t w = input.map.width, h = input.map.height;
    const uint32_t patch = options_.patch ? options_.patch : rmq_default_patch(w, h);
    if (patch > std::min(w, h))
      throw Error(ExitCode::bad_command_line,
                  "--patch " + std::to_string(patch) + " does not fit the " + std::to_string(w) + "x" +
                      std::to_string(h) + " example (at most " + std::to_string(std::bit_floor(std::min(w, h))) + ")",
                  options_.input.path);
    const double load_seconds = timer.lap();
    const AssetWriter writer = bake_rmq_asset(input, patch, options_.bits, progress);
    const double bake_seconds = timer.lap();
    options_.output.write_asset(writer);
    const double write_seconds = timer.lap();
    if (!options_.run.quiet) {
      const RmqLayout layout{w, h, patch, rmq_levels_for_patch(patch), options_.bits};
      std::cout << "rmq: wrote " << options_.output.path << " (" << w << "x" << h << ", patch " << patch
                << ", levels 0.." << layout.levels - 1 << ", " << options_.bits << " bits, table "
                << layout.table_bytes() << " bytes = " << std::fixed << std::setprecision(2)
                << double(layout.table_bytes()) / (1024.0 * 1024.0) << " MiB";
      const uint64_t repaired = input.record.repaired_texels;
      if (repaired) std::cout << ", " << repaired << " invalid texel" << (repaired == 1 ? "" : "s") << " repaired";
      std::cout << std::setprecision(3) << "); load " << load_seconds << " s, bake " << bake_seconds << " s, write "
                << write_seconds << " s\n";
    }
    return 0;
  }

 private:
  struct Options {
    NormalMapInput input;
    OutputOption output;
    uint32_t patch = 0;  // 0: the default for the example's size
    uint32_t bits = 16;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_rmq_command() { return std::make_unique<RmqCommand>(); }

}  // namespace mbk::cli
