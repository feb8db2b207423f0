// `microbake synth INPUT -o OUT.{exr,png} --level T --window X,Y,W,H [--seed S] [--jitter R,...] [--passes N]
// [--no-correction]`: synthesizes a window of a multiscale texture from an analysed exemplar graph ([Han08] thesis
// Sec. 5.2.2; libbake/synth/multiscale_synthesis.h). Deterministic: a window synthesized alone has the same pixels
// as the same region of a larger window, whatever the thread count.
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "cli/synthesis_options.h"
#include "formats/asset.h"
#include "formats/error.h"
#include "libbake/image/normal_map_encoding.h"
#include "libbake/synth/multiscale_synthesis.h"

namespace mbk::cli {
namespace {

class SynthCommand : public BakingCommand {
 public:
  SynthCommand() : BakingCommand("synth", "synthesized window (.exr float, or .png 16-bit)") {}

 private:
  void add_inputs(CLI::App& app) override {
    app.add_option("INPUT", path_, "Analysed exemplar graph (.mbk from `microbake graph`)")->required();
    add_window_options(app, window_options_, true, "");
  }

  std::vector<std::string> output_extensions() const override { return {".png", ".exr"}; }

  void check_inputs() override {
    const WindowRectangle w = parse_window(window_options_.window, kMaxWindowSide);
    synthesis_.x = w.x;
    synthesis_.y = w.y;
    synthesis_.width = uint32_t(w.width);
    synthesis_.height = uint32_t(w.height);
    synthesis_.jitter = parse_jitter(window_options_.jitter);
    synthesis_.correct_inconsistency = !window_options_.no_correction;
    synthesis_.level = parameters().at("level");
    synthesis_.seed = parameters().at("seed");
    synthesis_.passes = parameters().at("passes");
  }

  void load() override { graph_ = read_graph_tables(Asset::open(path_)); }

  void bake(Progress& progress) override { window_image_ = synthesize_window(graph_, synthesis_, progress); }

  void write(const OutputOption& output) const override {
    output.write_with([&](const std::filesystem::path& temporary) {
      if (!graph_.layout.normal_map) return save_image(temporary, window_image_, {}, output.path);
      // Encoded as every baker reads normal maps back (16-bit PNG (n + 1) / 2, float EXR n).
      save_normal_image(temporary, window_image_, YConvention::plus_y, output.path);
    });
  }

  std::string bake_stage() const override { return "synthesis"; }

  std::string bake_rate(double seconds) const override {
    std::ostringstream s;
    s << std::setprecision(3) << " ("
      << double(window_image_.width) * window_image_.height / 1e6 / std::max(seconds, 1e-9) << " megapixels/s)";
    return s.str();
  }

  // The output is an image, not an asset: its statistics are the window's (level and seed are parameters).
  nlohmann::json statistics() const override {
    return {{"width", window_image_.width},
            {"height", window_image_.height},
            {"channels", window_image_.channels},
            {"x", synthesis_.x},
            {"y", synthesis_.y}};
  }

  std::string summary() const override {
    return std::to_string(window_image_.width) + "x" + std::to_string(window_image_.height) + " at level " +
           std::to_string(synthesis_.level) + ", origin " + std::to_string(synthesis_.x) + "," +
           std::to_string(synthesis_.y);
  }

  std::string path_;
  WindowOptions window_options_;
  SynthesisOptions synthesis_;
  GraphTables graph_;
  Image window_image_;
};

}  // namespace

std::unique_ptr<Command> make_synth_command() { return std::make_unique<SynthCommand>(); }

}  // namespace mbk::cli
