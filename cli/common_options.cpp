// Shared options (see common_options.h).
#include "cli/common_options.h"

#include "cli/parameter_options.h"

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
  add_parameter_option(
      app, integer_option("--threads", 0, 1024, 0, "Worker threads (0 = all cores); outputs do not depend on it"),
      o.threads);
  app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
  Parameter progress;
  progress.option = "--progress";
  progress.type = ParameterType::choice;
  progress.choices = {"auto", "always", "never"};
  progress.default_value = "auto";
  progress.doc = "Progress bar on stderr: auto (only on a terminal), always, never";
  add_parameter_option(app, progress, o.progress);
}

void add_format_option(CLI::App& app, OutputFormat& format) {
  Parameter p;
  p.option = "--format";
  p.type = ParameterType::choice;
  p.choices = {"text", "json"};
  p.doc = "Report format";
  app.add_option_function<std::string>(
         p.option,
         [&format](const std::string& name) { format = name == "json" ? OutputFormat::json : OutputFormat::text; },
         p.doc)
      ->transform(parameter_validator(p))
      ->type_name(parameter_label(p))
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
  app.add_option("-o,--output", output.path, "Write the " + what + " here (written whole or not at all)")
      ->type_name("FILE")
      ->required();
}

NormalMapLoadOptions NormalMapInput::load_options() const {
  NormalMapLoadOptions o;
  o.convention = parse_convention_request(convention);
  o.invalid = repair_invalid ? InvalidTexelPolicy::repair : InvalidTexelPolicy::error;
  return o;
}

void add_normal_map_input(CLI::App& app, NormalMapInput& input) {
  app.add_option("INPUT", input.path, "Normal map (any image OpenImageIO reads: PNG, EXR, TGA, JPEG, TIFF)")
      ->required();
  app.add_option("--convention", input.convention,
                 "Green channel convention of the input: auto (told from the curl of its slopes; read as +Y with a "
                 "warning when it cannot tell), +Y (OpenGL) or -Y (DirectX, warned about when the slopes say +Y); "
                 "any case")
      ->type_name("auto|+Y|-Y")
      ->default_val("auto");
  app.add_flag(
      "--repair-invalid", input.repair_invalid,
      "Repair invalid texels instead of failing: NaN/Inf/zero -> (0,0,1), z < 0 -> z = 0 (recorded in metadata)");
}

}  // namespace mbk::cli
