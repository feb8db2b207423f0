// The shared skeleton of the baking commands (see baking_command.h).
#include "cli/baking_command.h"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/stage_timer.h"
#include "formats/asset.h"
#include "formats/atomic_file.h"
#include "formats/error.h"
#include "formats/file_extension.h"
#include "libbake/image/image_io.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk::cli {

BakingCommand::BakingCommand(std::string technique, std::string output_what)
    : technique_(std::move(technique)), output_what_(std::move(output_what)) {}

void BakingCommand::add_options(CLI::App& app) {
  add_inputs(app);
  add_output_option(app, output_, output_what_);
  schema_options_.add(app, technique_schema(technique_));
  add_format_option(app, format_);
  add_run_options(app, run_);
}

void BakingCommand::check() {
  parameters_ = schema_options_.values();
  check_inputs();
  const std::vector<std::string> allowed = output_extensions();
  if (allowed.size() == 1) {
    output_.require_extension(allowed[0]);
  } else if (std::find(allowed.begin(), allowed.end(), lower_extension(output_.path)) == allowed.end()) {
    std::string list;
    for (const std::string& e : allowed) list += (list.empty() ? "" : " or ") + e;
    throw Error(ExitCode::bad_command_line, "the output must end in " + list, output_.path);
  }
  output_.check_writable();
}

void BakingCommand::write(const OutputOption& output) const { output.write_asset(*asset_); }

nlohmann::json BakingCommand::statistics() const {
  return Asset::parse_structure(read_file_bytes(output_.path), output_.path).metadata().at("statistics");
}

int BakingCommand::run() {
  run_.apply();
  Progress progress(run_.progress_mode());
  StageTimer timer;
  load();
  const double load_seconds = timer.lap();
  if (lower_extension(output_.path) != ".mbk") start_loading_image_io();  // overlapping the bake
  bake(progress);
  const double bake_seconds = timer.lap();
  write(output_);
  const double write_seconds = timer.lap();
  if (format_ == OutputFormat::json) {
    nlohmann::json report = {{"schema", "microbake.baker/1"},
                             {"technique", technique_},
                             {"output", output_.path},
                             {"output_bytes", std::filesystem::file_size(output_.path)},
                             {"summary", summary()},
                             {"repaired_texels", repaired_texels()},
                             {"parameters", parameters_},
                             {"bake_stage", bake_stage()},
                             {"seconds", {{"load", load_seconds}, {"bake", bake_seconds}, {"write", write_seconds}}}};
    asset_.reset();  // statistics() reads the file back: its bytes are then in memory once, as while baking
    report["statistics"] = statistics();
    std::cout << report.dump(2) << "\n";
  } else if (!run_.quiet) {
    std::ostringstream line;
    line << technique_ << ": wrote " << output_.path << " (" << summary();
    if (const uint64_t repaired = repaired_texels())
      line << "; " << repaired << " invalid texel" << (repaired == 1 ? "" : "s") << " repaired";
    line << std::setprecision(3) << "); load " << load_seconds << " s, " << bake_stage() << " " << bake_seconds << " s"
         << bake_rate(bake_seconds) << ", write " << write_seconds << " s\n";
    std::cout << line.str();
  }
  return 0;
}

void NormalMapBakingCommand::add_inputs(CLI::App& app) { add_normal_map_input(app, input_); }

void NormalMapBakingCommand::check_inputs() { (void)input_.load_options(); }

void NormalMapBakingCommand::load() { map_ = load_normal_map(input_.path, input_.load_options()); }

LoadedNormalMap NormalMapBakingCommand::take_map() {
  LoadedNormalMap taken = std::move(map_);
  map_.map.width = taken.map.width;
  map_.map.height = taken.map.height;
  map_.record = taken.record;
  return taken;
}

std::string NormalMapBakingCommand::map_size() const {
  return std::to_string(map_.map.width) + "x" + std::to_string(map_.map.height);
}

}  // namespace mbk::cli
