// `microbake synth GRAPH.mbk -o OUT.{exr,png} --level T --window X,Y,W,H [--seed S] [--jitter R,...] [--passes N]
// [--no-correction]`: synthesizes a window of a multiscale texture from an analysed exemplar graph ([Han08] thesis
// Sec. 5.2.2; libbake/synth/multiscale_synthesis.h). Deterministic: a window synthesized alone has the same pixels
// as the same region of a larger window, whatever the thread count.
#include <cctype>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/stage_timer.h"
#include "formats/asset.h"
#include "formats/file_extension.h"
#include "libbake/image/normal_map_encoding.h"
#include "libbake/synth/multiscale_synthesis.h"

namespace mbk::cli {
namespace {

// The comma-separated numbers of an option ("1,0.6,0.4"); Error(bad_command_line) naming the option and the part
// that is empty, not a whole number (no leading blanks, nothing after it) or refused by `accept`. A trailing comma
// is an empty part.
template <class Accept>
std::vector<double> comma_separated(const std::string& text, const std::string& option, const std::string& expected,
                                    Accept accept) {
  std::vector<double> values;
  std::stringstream in(text + ",");  // the extra comma makes a trailing one show up as an empty part
  for (std::string part; std::getline(in, part, ',');) {
    size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(part, &used);
    } catch (const std::exception&) {
      used = std::string::npos;
    }
    if (part.empty() || std::isspace(static_cast<unsigned char>(part[0])) || used != part.size() || !accept(v))
      throw Error(ExitCode::bad_command_line, option + ": '" + part + "' is not " + expected, option);
    values.push_back(v);
  }
  return values;
}

class SynthCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("GRAPH", options_.graph, "Analysed exemplar graph (.mbk from `microbake graph`)")->required();
    add_output_option(app, options_.output, "the synthesized window (.exr float, or .png 16-bit)");
    app.add_option(
           "--level", options_.synthesis.level,
           "Synthesis level T (0..40): a texel of the root's coarsest stack level is 2^T pixels wide there, a texel "
           "of the root itself 2^(T - L)")
        ->required();
    app.add_option("--window", options_.window, "X,Y,W,H: the window's origin and size in pixels of level T")
        ->required();
    app.add_option("--seed", options_.synthesis.seed, "Jitter hash seed")->default_val(1u);
    app.add_option("--jitter", options_.jitter,
                   "Per-level randomness r_t in [0, 1], comma-separated from level 0; the last value repeats")
        ->default_val("1,0.6,0.4,0.3");
    app.add_option("--passes", options_.synthesis.passes, "Correction passes per level (4 sub-passes each)")
        ->check(CLI::Range(1u, 8u))
        ->default_val(2u);
    app.add_flag("--no-correction", options_.no_correction,
                 "Ignore the transfer functions (inconsistency correction, Sec. 5.3), to compare");
    add_run_options(app, options_.run);
  }

  void check() override {
    const std::string ext = lower_extension(options_.output.path);
    if (ext != ".png" && ext != ".exr")
      throw Error(ExitCode::bad_command_line, "synth writes .png (16-bit) or .exr (float) files, not '" + ext + "'",
                  options_.output.path);
    options_.output.check_writable();
    const std::vector<double> w = comma_separated(options_.window, "--window", "an integer",
                                                  [](double v) { return v == std::floor(v) && std::abs(v) <= 0x1p62; });
    if (w.size() != 4 || w[2] < 1 || w[3] < 1 || w[2] > 65536 || w[3] > 65536)
      throw Error(ExitCode::bad_command_line, "--window must be X,Y,W,H with 1 <= W, H <= 65536", "--window");
    options_.synthesis.x = int64_t(w[0]);
    options_.synthesis.y = int64_t(w[1]);
    options_.synthesis.width = uint32_t(w[2]);
    options_.synthesis.height = uint32_t(w[3]);
    options_.synthesis.jitter = comma_separated(options_.jitter, "--jitter", "a number in [0, 1]",
                                                [](double v) { return v >= 0.0 && v <= 1.0; });
    options_.synthesis.correct_inconsistency = !options_.no_correction;
  }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    StageTimer timer;
    const GraphTables graph = read_graph_tables(Asset::open(options_.graph));
    const double load_seconds = timer.lap();
    const Image window = synthesize_window(graph, options_.synthesis, progress);
    const double synth_seconds = timer.lap();
    options_.output.write_with([&](const std::filesystem::path& temporary) {
      if (!graph.layout.normal_map) return save_image(temporary, window, {}, options_.output.path);
      NormalMap map;  // encoded as every baker reads normal maps back (16-bit PNG (n + 1) / 2, float EXR n)
      map.width = window.width;
      map.height = window.height;
      for (size_t i = 0; i < window.pixels.size(); i += 3)
        map.texels.push_back(Vec3f(window.pixels[i], window.pixels[i + 1], window.pixels[i + 2]));
      save_normal_map(temporary, map, YConvention::plus_y, options_.output.path);
    });
    const double write_seconds = timer.lap();
    if (!options_.run.quiet)
      std::cout << std::fixed << std::setprecision(3) << "synth: wrote " << options_.output.path << " (" << window.width
                << "x" << window.height << " at level " << options_.synthesis.level << ", origin "
                << options_.synthesis.x << "," << options_.synthesis.y << "); load " << load_seconds << " s, synthesis "
                << synth_seconds << " s (" << std::setprecision(3)
                << double(window.width) * window.height / 1e6 / std::max(synth_seconds, 1e-9)
                << " megapixels/s), write " << write_seconds << " s\n";
    return 0;
  }

 private:
  struct Options {
    std::string graph, window, jitter;
    OutputOption output;
    SynthesisOptions synthesis;
    bool no_correction = false;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_synth_command() { return std::make_unique<SynthCommand>(); }

}  // namespace mbk::cli
