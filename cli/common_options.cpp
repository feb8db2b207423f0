// Shared options (see common_options.h).
#include "cli/common_options.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <set>

#include "formats/atomic_file.h"
#include "formats/error.h"
#include "formats/file_extension.h"
#include "libbake/core/parallel.h"
#include "libbake/core/warnings.h"

namespace mbk::cli {

ProgressMode RunOptions::progress_mode() const {
  if (quiet || progress == "never") return ProgressMode::never;
  if (progress == "always") return ProgressMode::always;
  return ProgressMode::automatic;
}

void RunOptions::apply() const {
  set_thread_count(threads);
  if (quiet) {
    set_warning_handler({});
    return;
  }
  // A scene may read one map for several assets: its warning is printed once.
  set_warning_handler(
      [printed = std::make_shared<std::set<std::string>>()](const std::string& what, const std::string& where) {
        const std::string line = "microbake: warning: " + what + " (" + where + ")\n";
        if (printed->insert(line).second) std::fputs(line.c_str(), stderr);
      });
}

void add_run_options(CLI::App& app, RunOptions& o) {
  app.add_option("--threads", o.threads, "Worker threads (0 = all cores); outputs do not depend on it")
      ->check(CLI::Range(0, 1024))
      ->default_val(0);
  app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
  app.add_option("--progress", o.progress, "Progress bar on stderr: auto (only on a terminal), always, never")
      ->check(CLI::IsMember({"auto", "always", "never"}))
      ->default_val("auto");
}

CLI::Validator finite_number(double lo, double hi) {
  auto short_form = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return std::string(text);
  };
  const std::string range = hi == std::numeric_limits<double>::max()
                                ? "a finite number >= " + short_form(lo)
                                : "a number in [" + short_form(lo) + ", " + short_form(hi) + "]";
  return CLI::Validator(
      [=](std::string& value) -> std::string {
        double x = 0.0;
        size_t used = 0;
        try {
          x = std::stod(value, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != value.size() || !std::isfinite(x) || x < lo || x > hi)
          return "'" + (value.size() > 40 ? value.substr(0, 37) + "..." : value) + "' is not " + range;
        return {};
      },
      range, "finite number");
}

void add_format_option(CLI::App& app, OutputFormat& format) {
  app.add_option("--format", format, "Report format: text or json")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, OutputFormat>{{"text", OutputFormat::text}, {"json", OutputFormat::json}}))
      ->default_str("text");
}

void OutputOption::write_with(const std::function<void(const std::filesystem::path&)>& produce) const {
  AtomicFile file(path);
  produce(file.temporary_path());
  file.commit();
}

void OutputOption::check_writable() const { AtomicFile probe(path); }

void OutputOption::require_extension(const std::string& extension) const {
  if (lower_extension(path) != extension)
    throw Error(ExitCode::bad_command_line, "the output must end in " + extension, path);
}

void OutputOption::write_asset(const AssetWriter& asset) const { asset.write(path); }

void add_output_option(CLI::App& app, OutputOption& output, const std::string& what) {
  app.add_option("-o,--output", output.path, "Write the " + what + " here (written whole or not at all)")->required();
}

NormalMapLoadOptions NormalMapInput::load_options() const {
  NormalMapLoadOptions o;
  o.convention = parse_convention_request(convention);
  o.invalid = repair_invalid ? InvalidTexelPolicy::repair : InvalidTexelPolicy::error;
  return o;
}

void add_normal_map_input(CLI::App& app, NormalMapInput& input) {
  app.add_option("input", input.path, "Normal map (any image OpenImageIO reads: PNG, EXR, TGA, JPEG, TIFF)")
      ->required();
  app.add_option("--convention", input.convention,
                 "Green channel convention of the input: auto (told from the curl of its slopes; read as +Y with a "
                 "warning when it cannot tell), +Y (OpenGL) or -Y (DirectX, warned about when the slopes say +Y); "
                 "any case")
      ->default_val("auto");
  app.add_flag(
      "--repair-invalid", input.repair_invalid,
      "Repair invalid texels instead of failing: NaN/Inf/zero -> (0,0,1), z < 0 -> z = 0 (recorded in metadata)");
}

void print_bake_times(std::ostream& out, const InputRecord& input, double load_seconds, double bake_seconds,
                      double write_seconds) {
  const uint64_t repaired = input.repaired_texels;
  if (repaired) out << "; " << repaired << " invalid texel" << (repaired == 1 ? "" : "s") << " repaired";
  out << "); load " << load_seconds << " s, bake " << bake_seconds << " s, write " << write_seconds << " s\n";
}

void check_asset_bake(const NormalMapInput& input, const OutputOption& output) {
  (void)input.load_options();
  output.require_extension(".mbk");
  output.check_writable();
}

}  // namespace mbk::cli
