// The skeleton every baking command shares, written once: the positional INPUT, -o/--output, the technique's options
// generated from its schema (libbake/scene/technique_parameters.h), the run options; then run() loads, bakes and
// writes (atomically), timing each stage, and prints one summary line
//   "<technique>: wrote <output> (<what was baked>[; N invalid texels repaired]); load L s, bake B s, write W s",
// or with --format json one object of schema "microbake.baker/1" (formats/schema/baker.schema.json): the same facts
// plus the parameters, the stage times and the bake's statistics.
// A technique supplies only its parts: its inputs, how it loads and bakes, and what its summary says.
// NormalMapBakingCommand is the skeleton of the techniques that bake a normal map (mip, lut, rmq, sh, vmf, crease).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/parameter_options.h"
#include "formats/asset_writer.h"
#include "libbake/image/normal_map.h"

namespace mbk::cli {

class BakingCommand : public Command {
 public:
  void add_options(CLI::App& app) final;
  void check() final;
  int run() final;

 protected:
  // `technique` names the schema, the summary line and the bake stage's default name; `output_what` describes the
  // output file in -o's help.
  BakingCommand(std::string technique, std::string output_what);

  // The technique's parts, in the order they are called.
  virtual void add_inputs(CLI::App& app) = 0;  // the positional INPUT, and any other input
  virtual void check_inputs() {}               // rules across options, before any work
  virtual void load() = 0;                     // the "load" stage
  virtual void bake(Progress& progress) = 0;   // the "bake" stage: sets asset_, or whatever write() writes
  // Writes to the output; the default writes asset_.
  virtual void write(const OutputOption& output) const;
  // The text inside the summary line's parentheses.
  virtual std::string summary() const = 0;
  virtual uint64_t repaired_texels() const { return 0; }
  // What the summary line calls the bake stage ("bake"; graph: "analysis"), and any rate printed after its time.
  virtual std::string bake_stage() const { return "bake"; }
  virtual std::string bake_rate(double /*seconds*/) const { return ""; }
  // The statistics of the JSON report; the default is the written asset's metadata "statistics" (formats/SPEC.md),
  // read back from the file (whose structure and checksums are checked on the way).
  virtual nlohmann::json statistics() const;
  // The output's allowed extensions (lower case); the default is an asset.
  virtual std::vector<std::string> output_extensions() const { return {".mbk"}; }

  // The technique's parameters after parsing: every one of its schema, given or defaulted.
  const nlohmann::json& parameters() const { return parameters_; }
  const OutputOption& output() const { return output_; }
  const RunOptions& run_options() const { return run_; }

  std::optional<AssetWriter> asset_;

 private:
  std::string technique_, output_what_;
  SchemaOptions schema_options_;
  nlohmann::json parameters_;
  OutputOption output_;
  RunOptions run_;
  OutputFormat format_ = OutputFormat::text;
};

class NormalMapBakingCommand : public BakingCommand {
 protected:
  using BakingCommand::BakingCommand;
  void add_inputs(CLI::App& app) override;
  void check_inputs() override;
  void load() override;
  uint64_t repaired_texels() const override { return map_.record.repaired_texels; }

  const NormalMapInput& input() const { return input_; }
  const LoadedNormalMap& map() const { return map_; }
  // Moves the loaded map out, for a baker whose asset holds the map itself (mip: no second copy of the finest
  // level); map() keeps the size and the record, its texels are then empty.
  LoadedNormalMap take_map();
  // "WxH" of the loaded map.
  std::string map_size() const;

 private:
  NormalMapInput input_;
  LoadedNormalMap map_;
};

}  // namespace mbk::cli
