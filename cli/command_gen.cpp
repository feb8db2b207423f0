// `microbake gen KIND -o OUT.{png,exr} [--size N|WxH] [--seed S]`: writes a deterministic procedural
// normal map (libbake/gen/generator.h) as a 16-bit PNG or a 32-bit float EXR (+Y convention); for panels,
// --creases FILE.json also writes the exact crease lines (libbake/gen/panels.h) for `microbake crease`.
#include <charconv>
#include <fstream>
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/parameter_options.h"
#include "formats/error.h"
#include "formats/file_extension.h"
#include "libbake/crease/curve_set.h"
#include "libbake/gen/generator.h"
#include "libbake/gen/panels.h"
#include "libbake/image/normal_map_encoding.h"

namespace mbk::cli {
namespace {

// "N" (square) or "WxH", each side in 1..kMaxNormalMapSide.
MapSize parse_size(const std::string& text) {
  auto number = [&](std::string_view part) {
    uint32_t v = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (ec != std::errc() || end != part.data() + part.size() || part.empty() || v < 1 || v > kMaxNormalMapSide)
      throw Error(ExitCode::bad_command_line, "--size must be N or WxH with sides in 1.." +
                                                  std::to_string(kMaxNormalMapSide) + ", not '" + text + "'");
    return v;
  };
  const size_t x = text.find_first_of("xX");
  if (x == std::string::npos) {
    const uint32_t n = number(text);
    return {n, n};
  }
  return {number(std::string_view(text).substr(0, x)), number(std::string_view(text).substr(x + 1))};
}

class GenCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    std::string kinds = "What to generate: " + generator_names();
    for (const GeneratorKind& k : generator_kinds())
      kinds += "\n  " + std::string(k.name) + ": " + std::string(k.summary);
    app.add_option("KIND", options_.kind, kinds)->required();
    add_output_option(app, options_.output, "normal map (.png: 16-bit, .exr: 32-bit float)");
    app.add_option("--size", options_.size, "Size in texels: N (square) or WxH")
        ->type_name("N|WxH")
        ->default_val("512");
    add_parameter_option(app, integer_option("--seed", 0, 4294967295.0, 1, "Random seed"), options_.seed);
    app.add_option("--creases", options_.creases.path,
                   "panels only: also write the exact crease lines as a curves file (.json) for `microbake crease`")
        ->type_name("FILE");
    add_run_options(app, options_.run);
  }

  void check() override {
    if (!find_generator(options_.kind))
      throw Error(ExitCode::bad_command_line,
                  "unknown kind '" + options_.kind + "' (kinds: " + generator_names() + ")");
    size_ = parse_size(options_.size);
    const std::string ext = lower_extension(options_.output.path);
    if (ext != ".png" && ext != ".exr")
      throw Error(ExitCode::bad_command_line, "gen writes .png (16-bit) or .exr (float) files, not '" + ext + "'",
                  options_.output.path);
    options_.output.check_writable();
    if (!options_.creases.path.empty()) {
      if (options_.kind != "panels")
        throw Error(ExitCode::bad_command_line, "--creases is known only for kind panels, not '" + options_.kind + "'");
      options_.creases.require_extension(".json");
      options_.creases.check_writable();
    }
  }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    const NormalMap map = generate_normal_map(options_.kind, size_, options_.seed, progress);
    options_.output.write_with([&](const std::filesystem::path& temporary) {
      save_normal_map(temporary, map, YConvention::plus_y, options_.output.path);
    });
    if (!options_.creases.path.empty()) {
      CurveSet creases;
      for (const CreaseSegment& s : panel_creases(size_, options_.seed))
        creases.curves.push_back({{s.a, s.b}, false, ""});
      options_.creases.write_with([&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary);
        out << curves_to_json(creases).dump() << "\n";
        if (!out) throw Error(ExitCode::io_failure, "cannot write", options_.creases.path);
      });
    }
    if (!options_.run.quiet)
      std::cout << "gen: wrote " << options_.output.path << " (" << options_.kind << ", " << size_.width << "x"
                << size_.height << ", seed " << options_.seed << ", +Y)\n";
    return 0;
  }

 private:
  struct Options {
    std::string kind;
    OutputOption output;
    OutputOption creases;  // optional
    std::string size = "512";
    uint32_t seed = 1;
    RunOptions run;
  } options_;
  MapSize size_;
};

}  // namespace

std::unique_ptr<Command> make_gen_command() { return std::make_unique<GenCommand>(); }

}  // namespace mbk::cli
