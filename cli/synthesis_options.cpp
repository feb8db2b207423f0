// The options of a synthesized window (see synthesis_options.h).
#include "cli/synthesis_options.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "formats/error.h"

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

}  // namespace

void add_window_options(CLI::App& app, WindowOptions& options, bool window_required, const std::string& group) {
  CLI::Option* window = app.add_option("--window", options.window, "The window's origin and size in pixels of level T")
                            ->type_name("X,Y,W,H");
  if (window_required) window->required();
  CLI::Option* jitter =
      app.add_option("--jitter", options.jitter,
                     "Per-level randomness r_t in [0, 1], comma-separated from level 0; the last value repeats")
          ->type_name("R0,R1,...")
          ->default_val(options.jitter);
  CLI::Option* no_correction = app.add_flag("--no-correction", options.no_correction,
                                            "Ignore the transfer functions (inconsistency correction, Sec. 5.3), to "
                                            "compare");
  if (!group.empty())
    for (CLI::Option* o : {window, jitter, no_correction}) o->group(group);
}

WindowRectangle parse_window(const std::string& text, uint64_t max_side) {
  const std::vector<double> w = comma_separated(text, "--window", "an integer",
                                                [](double v) { return v == std::floor(v) && std::abs(v) <= 0x1p62; });
  if (w.size() != 4 || w[2] < 1 || w[3] < 1 || w[2] > double(max_side) || w[3] > double(max_side))
    throw Error(ExitCode::bad_command_line, "--window must be X,Y,W,H with 1 <= W, H <= " + std::to_string(max_side),
                "--window");
  return {int64_t(w[0]), int64_t(w[1]), uint64_t(w[2]), uint64_t(w[3])};
}

std::vector<double> parse_jitter(const std::string& text) {
  return comma_separated(text, "--jitter", "a number in [0, 1]", [](double v) { return v >= 0.0 && v <= 1.0; });
}

}  // namespace mbk::cli
