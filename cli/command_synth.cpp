// `microbake synth INPUT -o OUT.{exr,png} --level T --window X,Y,W,H [--seed S] [--jitter R,...] [--passes N]
// [--no-correction]`: synthesizes a window of a multiscale texture from an analysed exemplar graph ([Han08] thesis
// Sec. 5.2.2; libbake/synth/multiscale_synthesis.h). Deterministic: a window synthesized alone has the same pixels
// as the same region of a larger window, whatever the thread count.
#include <cctype>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "formats/asset.h"
#include "formats/error.h"
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

class SynthCommand : public BakingCommand {
 public:
  SynthCommand() : BakingCommand("synth", "synthesized window (.exr float, or .png 16-bit)") {}

 private:
  void add_inputs(CLI::App& app) override {
    app.add_option("INPUT", path_, "Analysed exemplar graph (.mbk from `microbake graph`)")->required();
    app.add_option("--window", window_, "The window's origin and size in pixels of level T")
        ->type_name("X,Y,W,H")
        ->required();
    app.add_option("--jitter", jitter_,
                   "Per-level randomness r_t in [0, 1], comma-separated from level 0; the last value repeats")
        ->type_name("R0,R1,...")
        ->default_val("1,0.6,0.4,0.3");
    app.add_flag("--no-correction", no_correction_,
                 "Ignore the transfer functions (inconsistency correction, Sec. 5.3), to compare");
  }

  std::vector<std::string> output_extensions() const override { return {".png", ".exr"}; }

  void check_inputs() override {
    const std::vector<double> w = comma_separated(window_, "--window", "an integer",
                                                  [](double v) { return v == std::floor(v) && std::abs(v) <= 0x1p62; });
    if (w.size() != 4 || w[2] < 1 || w[3] < 1 || w[2] > 65536 || w[3] > 65536)
      throw Error(ExitCode::bad_command_line, "--window must be X,Y,W,H with 1 <= W, H <= 65536", "--window");
    synthesis_.x = int64_t(w[0]);
    synthesis_.y = int64_t(w[1]);
    synthesis_.width = uint32_t(w[2]);
    synthesis_.height = uint32_t(w[3]);
    synthesis_.jitter =
        comma_separated(jitter_, "--jitter", "a number in [0, 1]", [](double v) { return v >= 0.0 && v <= 1.0; });
    synthesis_.correct_inconsistency = !no_correction_;
    synthesis_.level = parameters().at("level");
    synthesis_.seed = parameters().at("seed");
    synthesis_.passes = parameters().at("passes");
  }

  void load() override { graph_ = read_graph_tables(Asset::open(path_)); }

  void bake(Progress& progress) override { window_image_ = synthesize_window(graph_, synthesis_, progress); }

  void write(const OutputOption& output) const override {
    output.write_with([&](const std::filesystem::path& temporary) {
      if (!graph_.layout.normal_map) return save_image(temporary, window_image_, {}, output.path);
      NormalMap map;  // encoded as every baker reads normal maps back (16-bit PNG (n + 1) / 2, float EXR n)
      map.width = window_image_.width;
      map.height = window_image_.height;
      for (size_t i = 0; i < window_image_.pixels.size(); i += 3)
        map.texels.push_back(Vec3f(window_image_.pixels[i], window_image_.pixels[i + 1], window_image_.pixels[i + 2]));
      save_normal_map(temporary, map, YConvention::plus_y, output.path);
    });
  }

  std::string bake_stage() const override { return "synthesis"; }

  std::string bake_rate(double seconds) const override {
    std::ostringstream s;
    s << std::setprecision(3) << " ("
      << double(window_image_.width) * window_image_.height / 1e6 / std::max(seconds, 1e-9) << " megapixels/s)";
    return s.str();
  }

  std::string summary() const override {
    return std::to_string(window_image_.width) + "x" + std::to_string(window_image_.height) + " at level " +
           std::to_string(synthesis_.level) + ", origin " + std::to_string(synthesis_.x) + "," +
           std::to_string(synthesis_.y);
  }

  std::string path_, window_, jitter_;
  bool no_correction_ = false;
  SynthesisOptions synthesis_;
  GraphTables graph_;
  Image window_image_;
};

}  // namespace

std::unique_ptr<Command> make_synth_command() { return std::make_unique<SynthCommand>(); }

}  // namespace mbk::cli
