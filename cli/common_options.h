// Options written once and reused by every command, with the same names and wording everywhere:
// run options (--threads, --quiet, --progress), --format text|json, -o/--output (whose temporary-then-
// rename writing lives here, so no command can forget it), the normal-map input (auto/+Y/-Y, repair), and the
// stderr printing of the library's warnings (libbake/core/warnings.h), which --quiet silences.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include <CLI/CLI.hpp>

#include "formats/asset_writer.h"
#include "libbake/core/progress.h"
#include "libbake/image/normal_map.h"

namespace mbk::cli {

struct RunOptions {
  int threads = 0;
  bool quiet = false;
  std::string progress = "auto";
  // The progress reporter --progress/--quiet ask for.
  ProgressMode progress_mode() const;
  // Applies --threads, and prints the library's warnings on stderr (`microbake: warning: <what> (<where>)`, each
  // distinct line once) unless --quiet.
  void apply() const;
};
void add_run_options(CLI::App& app, RunOptions& options);

enum class OutputFormat { text, json };
void add_format_option(CLI::App& app, OutputFormat& format);

struct OutputOption {
  std::string path;
  // Calls produce(temporary) to write the output to a temporary path beside the destination (same
  // extension), then flushes and renames it into place. On any exception the temporary is removed.
  void write_with(const std::function<void(const std::filesystem::path& temporary)>& produce) const;
  // Writes the asset atomically, streamed section by section.
  void write_asset(const AssetWriter& asset) const;
  // Fails early (Error io_failure) when the output cannot be written: its folder is missing or the path is a
  // folder. Commands call it from check(), before any long work.
  void check_writable() const;
  // Error(bad_command_line) unless the path ends in `extension` (e.g. ".mbk"), compared case-insensitively.
  void require_extension(const std::string& extension) const;
};
// -o/--output, required. `what` describes the file (e.g. "output asset (.mbk)").
void add_output_option(CLI::App& app, OutputOption& output, const std::string& what);

struct NormalMapInput {
  std::string path;
  std::string convention = "auto";
  bool repair_invalid = false;
  NormalMapLoadOptions load_options() const;
};
// The positional INPUT argument plus --convention (auto, the default, +Y or -Y) and --repair-invalid.
void add_normal_map_input(CLI::App& app, NormalMapInput& input);

}  // namespace mbk::cli
