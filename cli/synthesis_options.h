// The options of a synthesized window that `microbake synth` takes and `microbake plan --synth` hands on to each tile
// ([Han08] thesis Sec. 5.2.2; libbake/synth/multiscale_synthesis.h): --window X,Y,W,H, --jitter R0,R1,... and
// --no-correction, declared and checked here once. (The level, seed and passes are the "synth" technique's schema
// parameters, libbake/scene/technique_parameters.cpp.)
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "libbake/synth/multiscale_synthesis.h"

namespace mbk::cli {

// The widest window side one `synth` command synthesizes (its pixel count has a limit of its own,
// docs/commands/synth.md).
inline constexpr uint64_t kMaxWindowSide = 65536;

struct WindowOptions {
  std::string window;                    // "X,Y,W,H" as given
  std::string jitter = "1,0.6,0.4,0.3";  // "R0,R1,..." as given
  bool no_correction = false;
};

// Adds --window (required when `window_required`), --jitter and --no-correction to `app`, under help heading `group`
// ("" = the plain options).
void add_window_options(CLI::App& app, WindowOptions& options, bool window_required, const std::string& group);

// The window's origin and size: Error(bad_command_line) naming --window unless it is four integers X,Y,W,H with
// |X|, |Y| <= 2^62 and 1 <= W, H <= max_side.
struct WindowRectangle {
  int64_t x = 0, y = 0;
  uint64_t width = 0, height = 0;
};
WindowRectangle parse_window(const std::string& text, uint64_t max_side);

// The per-level jitter r_t: Error(bad_command_line) naming --jitter unless every part is a number in [0, 1].
std::vector<double> parse_jitter(const std::string& text);

}  // namespace mbk::cli
