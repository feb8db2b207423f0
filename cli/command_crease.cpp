// `microbake crease IN --curves FILE -o OUT.mbk [--smooth-iterations N] [--band B]`: bakes a normal map with
// discontinuity curves into asset kind `crease` ([Parilov05]; libbake/crease/crease_asset.h). Its summary
// line reports what the simplification did and the wall time of loading, baking and writing.
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/stage_timer.h"
#include "libbake/crease/crease_asset.h"

namespace mbk::cli {
namespace {

class CreaseCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    add_normal_map_input(app, options_.input);
    app.add_option("--curves", options_.curves,
                   "Discontinuity curves: .json ({\"curves\": [{\"points\": [[x, y], ...], \"closed\": false}]}) or "
                   ".svg (path with M L H V Z and m l h v z, polyline, polygon, line; viewBox mapped onto the map), "
                   "in texel coordinates x right, y down, the map spanning [0, W] x [0, H]")
        ->required();
    add_output_option(app, options_.output, "crease asset (.mbk)");
    app.add_option("--smooth-iterations", options_.bake.smooth_iterations,
                   "Constrained Laplacian smoothing iterations of the gradient map (0..10000)")
        ->check(CLI::Range(0u, kCreaseMaxSmoothIterations))
        ->default_val(kCreaseDefaultSmoothIterations);
    app.add_option("--band", options_.bake.band,
                   "Texels around the curves where the distance map is exact by brute force (beyond: nearest-segment "
                   "propagation)")
        ->check(finite_number(1e-6, 1e6))
        ->default_val(kCreaseDefaultBand);
    add_run_options(app, options_.run);
  }

  void check() override { check_asset_bake(options_.input, options_.output); }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    StageTimer timer;
    const LoadedNormalMap input = load_normal_map(options_.input.path, options_.input.load_options());
    const CurveSet curves = load_curves(options_.curves, input.map.width, input.map.height);
    const CurvesRecord record = curves_record(options_.curves, curves);
    const double load_seconds = timer.lap();
    const BakedCrease baked = bake_crease(input.map, curves, options_.bake, progress);
    const double bake_seconds = timer.lap();
    options_.output.write_asset(crease_asset_writer(baked, options_.bake, input.record, record));
    const double write_seconds = timer.lap();
    if (!options_.run.quiet) {
      const SimplifyStatistics& s = baked.simplify;
      std::cout << "crease: wrote " << options_.output.path << " (" << input.map.width << "x" << input.map.height
                << ", " << record.curves << " curve" << (record.curves == 1 ? "" : "s") << ", " << record.segments
                << " segments -> " << baked.network_segments << " cell segments in " << s.cells_with_segments
                << " cells, " << s.merged_edges << " merged crossings (max shift " << std::setprecision(3)
                << s.max_merge_shift << " texels), " << s.deleted_segments << " deleted; band " << options_.bake.band
                << ", " << options_.bake.smooth_iterations << " smoothing iterations); " << std::fixed << "load "
                << load_seconds << " s, bake " << bake_seconds << " s, write " << write_seconds << " s\n";
    }
    return 0;
  }

 private:
  struct Options {
    NormalMapInput input;
    std::string curves;
    OutputOption output;
    CreaseBakeOptions bake;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_crease_command() { return std::make_unique<CreaseCommand>(); }

}  // namespace mbk::cli
