// `microbake colormap MAP -o OUT.mbk [--size WxH] [--sigma-max S] [--encoding auto|srgb|linear]`: bakes a colour
// map (gradient image or JSON stops) convolved with Gaussians into a (mean, sigma) table ([Heitz13] Eq. 10; asset
// kind `colormap`, libbake/colormap/colormap_table.h).
#include <iomanip>
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/stage_timer.h"
#include "formats/error.h"
#include "libbake/colormap/colormap_source.h"
#include "libbake/colormap/colormap_table.h"

namespace mbk::cli {
namespace {

// "WxH" -> (W, H); Error(bad_command_line) otherwise (the range is checked by the baker).
std::pair<uint32_t, uint32_t> parse_size(const std::string& text) {
  const size_t x = text.find_first_of("xX");
  try {
    if (x != std::string::npos && x > 0 && x + 1 < text.size() &&
        text.find_first_not_of("0123456789xX") == std::string::npos) {
      const unsigned long w = std::stoul(text.substr(0, x)), h = std::stoul(text.substr(x + 1));
      if (w <= kColormapMaxSide && h <= kColormapMaxSide) return {uint32_t(w), uint32_t(h)};
    }
  } catch (const std::exception&) {
  }
  throw Error(ExitCode::bad_command_line, "--size must be WxH with each side in " + std::to_string(kColormapMinSide) +
                                              ".." + std::to_string(kColormapMaxSide) + ", not '" + text + "'");
}

class ColormapCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("MAP", options_.map,
                   "Colour map: a gradient image (one row, or the middle row is used) or JSON colour stops (.json)")
        ->required();
    add_output_option(app, options_.output, "prefiltered colour-map asset (.mbk)");
    app.add_option("--size", options_.size, "Table size: W mean samples x H standard-deviation samples")
        ->default_val("256x256");
    app.add_option("--sigma-max", options_.sigma_max,
                   "Largest standard deviation tabulated (driver units); default: half the map's domain")
        ->check(finite_number(1e-12));
    app.add_option("--encoding", options_.encoding,
                   "Colour encoding of MAP: auto (integer images and JSON default sRGB, float images linear), "
                   "srgb or linear")
        ->default_val("auto");
    add_run_options(app, options_.run);
  }

  void check() override {
    (void)parse_color_encoding(options_.encoding);
    std::tie(options_.table.width, options_.table.height) = parse_size(options_.size);
    options_.table.sigma_max = options_.sigma_max;
    options_.output.require_extension(".mbk");
    options_.output.check_writable();
  }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    StageTimer timer;
    const LoadedColormap source = load_colormap_source(options_.map, parse_color_encoding(options_.encoding));
    const double load_seconds = timer.lap();
    options_.table.mean_min = source.domain_min;
    options_.table.mean_max = source.domain_max;
    const BakedColormap baked = bake_colormap_table(source.curve, options_.table, progress);
    const AssetWriter writer = colormap_asset_writer(baked, source.record, source.encoding);
    const double bake_seconds = timer.lap();
    options_.output.write_asset(writer);
    const double write_seconds = timer.lap();
    if (!options_.run.quiet) {
      const ColormapTable& t = baked.table;
      const ColormapTableStatistics& s = baked.statistics;
      std::cout << std::setprecision(3) << "colormap: wrote " << options_.output.path << " ("
                << baked.curve.knots.size() << " knots, " << source.encoding << " -> linear; " << t.width << "x"
                << t.height << " table, mean " << t.mean_min << ".." << t.mean_max << ", sigma 0.." << t.sigma_max
                << "; lookup error max " << s.lookup_max_error << ", rms " << s.lookup_rms_error
                << "; naive C(mean) off by up to " << s.naive_max_error << "); load " << load_seconds << " s, bake "
                << bake_seconds << " s, write " << write_seconds << " s\n";
    }
    return 0;
  }

 private:
  struct Options {
    std::string map;
    OutputOption output;
    std::string size = "256x256";
    double sigma_max = 0.0;
    std::string encoding = "auto";
    ColormapTableOptions table;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_colormap_command() { return std::make_unique<ColormapCommand>(); }

}  // namespace mbk::cli
