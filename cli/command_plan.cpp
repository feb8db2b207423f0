// `microbake plan SCENE... -o FILE [--format ninja|make|commands|slurm] [--out-dir DIR] [--microbake PROGRAM]`:
// writes every asset the scenes call for as one plain `microbake <kind> INPUT [options] -o PATH` command
// (libbake/scene/asset_command.h) into a file for a build tool or scheduler (cli/plan_files.h). Assets are
// content-addressed (libbake/scene/bake_plan.h), so the names are known before any bake, an asset several scenes
// share is listed once (libbake/scene/batch_plan.h), and the files are the ones `bake` writes and `render` reads.
// The asset folders are created here, so that every tool finds them.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <set>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/parameter_options.h"
#include "cli/plan_files.h"
#include "formats/error.h"
#include "libbake/scene/asset_command.h"
#include "libbake/scene/batch_plan.h"

namespace mbk::cli {
namespace {

namespace fs = std::filesystem;

class PlanCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("SCENE", options_.scenes, "Scene files (JSON); an asset several of them call for is planned once")
        ->required();
    add_output_option(app, options_.output,
                      "plan (slurm: the job script, and its commands file beside it with extension .commands)");
    Parameter format;
    format.option = "--format";
    format.type = ParameterType::choice;
    format.choices = {"ninja", "make", "commands", "slurm"};
    format.default_value = "ninja";
    format.doc =
        "ninja: a build.ninja; make: a Makefile; commands: one command per line (GNU parallel); slurm: a job-array "
        "script running line i of its commands file in task i";
    add_parameter_option(app, format, options_.format);
    app.add_option("--out-dir", options_.out_dir,
                   "Asset folder of every scene (default: each scene's <scene folder>/<scene stem>.assets)")
        ->type_name("DIR");
    app.add_option("--microbake", options_.program, "The program the commands run (default: microbake, found on PATH)")
        ->type_name("PROGRAM");
  }

  void check() override {
    if (options_.format == "slurm" && slurm_commands_path(options_.output.path) == fs::path(options_.output.path))
      throw Error(ExitCode::bad_command_line, "the slurm script's commands file would overwrite it: name it otherwise",
                  options_.output.path);
    options_.output.check_writable();
  }

  int run() override {
    const std::vector<BatchScene> scenes = load_batch_scenes(options_.scenes, options_.out_dir);
    const std::vector<BatchAsset> batch = plan_batch(scenes);
    std::vector<PlannedBake> bakes;
    PlanRegeneration regeneration{regeneration_command(), {}};
    for (const std::string& name : options_.scenes) regeneration.inputs.push_back(name);
    for (const BatchAsset& a : batch) {
      if (a.file.empty())
        throw Error(ExitCode::io_failure,
                    a.missing_input + " not found: " + use_text(a.uses.front()) + " needs it for its " +
                        a.planned.recipe.kind + " asset",
                    a.uses.front().scene);
      PlannedBake b;
      b.output = a.file;
      for (const BakeInput& in : a.planned.recipe.inputs) {
        b.inputs.push_back(in.path);
        if (std::find(regeneration.inputs.begin(), regeneration.inputs.end(), in.path) == regeneration.inputs.end())
          regeneration.inputs.push_back(in.path);
      }
      b.command = asset_command(a.planned.recipe, a.file, options_.program);
      b.description = a.planned.recipe.kind + " " + a.file.string();
      bakes.push_back(std::move(b));
    }
    for (const BatchAsset& a : batch) {
      std::error_code ec;
      fs::create_directories(a.file.parent_path(), ec);
      if (ec)
        throw Error(ExitCode::io_failure, "cannot create the asset folder: " + ec.message(),
                    a.file.parent_path().string());
    }
    write(bakes, regeneration);
    size_t shared = 0;
    for (const BatchAsset& a : batch) {
      std::set<std::string> by;
      for (const BatchUse& u : a.uses) by.insert(u.scene);
      shared += by.size() > 1;
    }
    std::cout << "plan: wrote " << options_.output.path << " (" << options_.format << ", " << bakes.size() << " asset"
              << (bakes.size() == 1 ? "" : "s") << " from " << scenes.size() << " scene"
              << (scenes.size() == 1 ? "" : "s") << ", " << shared << " shared by several scenes)\n";
    return 0;
  }

 private:
  std::vector<std::string> regeneration_command() const {
    std::vector<std::string> words = {options_.program, "plan"};
    words.insert(words.end(), options_.scenes.begin(), options_.scenes.end());
    for (const std::string& w : {std::string("-o"), options_.output.path, std::string("--format"), options_.format})
      words.push_back(w);
    if (!options_.out_dir.empty()) words.insert(words.end(), {"--out-dir", options_.out_dir});
    if (options_.program != "microbake") words.insert(words.end(), {"--microbake", options_.program});
    return words;
  }

  void write(const std::vector<PlannedBake>& bakes, const PlanRegeneration& regeneration) const {
    const fs::path self = options_.output.path;
    auto write_text = [](const OutputOption& out, const std::string& text) {
      out.write_with([&](const fs::path& temporary) {
        std::ofstream file(temporary, std::ios::binary);
        file << text;
        if (!file.flush()) throw Error(ExitCode::io_failure, "cannot write", temporary.string());
      });
    };
    if (options_.format == "ninja") write_text(options_.output, ninja_file(bakes, regeneration, self));
    if (options_.format == "make") write_text(options_.output, make_file(bakes, regeneration, self));
    if (options_.format == "commands") write_text(options_.output, commands_file(bakes));
    if (options_.format == "slurm") {
      const fs::path commands = fs::absolute(slurm_commands_path(self)).lexically_normal();
      write_text(OutputOption{commands.string()}, commands_file(bakes));
      write_text(options_.output, slurm_script(bakes.size(), commands, fs::current_path()));
    }
  }

  struct Options {
    std::vector<std::string> scenes;
    OutputOption output;
    std::string format = "ninja";
    std::string out_dir;
    std::string program = "microbake";
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_plan_command() { return std::make_unique<PlanCommand>(); }

}  // namespace mbk::cli
