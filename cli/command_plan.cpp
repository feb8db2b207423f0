// `microbake plan [SCENE...] [--synth GRAPH --level T --window X,Y,W,H --tile N ...] -o FILE
// [--format ninja|make|commands|slurm] [--out-dir DIR] [--lines-per-task K] [--microbake PROGRAM]`:
// writes every asset the scenes call for as one plain `microbake <kind> INPUT [options] -o PATH` command
// (libbake/scene/asset_command.h), and a synthesis window as one `microbake synth` per tile (cli/synthesis_tiles.h),
// into a file for a build tool or scheduler (cli/plan_files.h). Assets are content-addressed
// (libbake/scene/bake_plan.h), so the names are known before any bake, an asset several scenes share is listed once
// (libbake/scene/batch_plan.h), and the files are the ones `bake` writes and `render` reads. The asset and tile
// folders are created here, so that every tool finds them.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <set>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/parameter_options.h"
#include "cli/plan_files.h"
#include "cli/synthesis_tiles.h"
#include "formats/error.h"
#include "libbake/scene/asset_command.h"
#include "libbake/scene/batch_plan.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk::cli {
namespace {

namespace fs = std::filesystem;

const char* kSynthesisGroup = "Synthesis tiles (with --synth)";

class PlanCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app_ = &app;
    app.add_option("SCENE", options_.scenes, "Scene files (JSON); an asset several of them call for is planned once");
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
                   "Asset folder of every scene (default: each scene's <scene folder>/<scene stem>.assets), and the "
                   "folder of the tiles (default: <graph folder>/<graph stem>.tiles)")
        ->type_name("DIR");
    add_parameter_option(app,
                         integer_option("--lines-per-task", 1, 65536, 1,
                                        "slurm: commands each array task runs, one after another (fewer tasks than "
                                        "commands, for clusters whose MaxArraySize is smaller)"),
                         options_.lines_per_task);
    app.add_option("--microbake", options_.program, "The program the commands run (default: microbake, found on PATH)")
        ->type_name("PROGRAM");
    app.add_option("--synth", options_.tiles.graph,
                   "Analysed exemplar graph (.mbk from `microbake graph`): plan the --window at --level as tiles, "
                   "one `microbake synth` each")
        ->type_name("GRAPH")
        ->group(kSynthesisGroup);
    synth_schema_.add_optional_group(app, technique_schema("synth"), kSynthesisGroup);
    add_window_options(app, options_.tiles.window, false, kSynthesisGroup);
    add_parameter_option(app,
                         integer_option("--tile", 1, 4096, 1024,
                                        "Tile side in pixels (the last row and column narrower); tiles are named "
                                        "<graph stem>.L<T>.<x>_<y>.<ext>, x, y the tile's origin"),
                         options_.tiles.tile)
        ->group(kSynthesisGroup);
    Parameter tile_format;
    tile_format.option = "--tile-format";
    tile_format.type = ParameterType::choice;
    tile_format.choices = {"exr", "png"};
    tile_format.default_value = "exr";
    tile_format.doc = "The tiles' image format: exr (float) or png (16-bit)";
    add_parameter_option(app, tile_format, options_.tile_format)->group(kSynthesisGroup);
  }

  void check() override {
    const bool synthesis = !options_.tiles.graph.empty();
    if (options_.scenes.empty() && !synthesis)
      throw Error(ExitCode::bad_command_line, "give scene files, or a graph to plan as tiles with --synth", "SCENE");
    for (const CLI::Option* o : app_->get_options())
      if (!synthesis && o->get_group() == kSynthesisGroup && o->count() > 0)
        throw Error(ExitCode::bad_command_line, o->get_name() + " plans synthesis tiles: give the graph with --synth",
                    o->get_name());
    if (synthesis) {
      options_.tiles.technique_values = synth_schema_.values();
      if (options_.tiles.technique_values.at("level").is_null())
        throw Error(ExitCode::bad_command_line, "--synth needs the synthesis level --level T", "--level");
      if (options_.tiles.window.window.empty())
        throw Error(ExitCode::bad_command_line, "--synth needs the whole window --window X,Y,W,H", "--window");
      options_.tiles.extension = "." + options_.tile_format;
      options_.tiles.out_dir = options_.out_dir.empty()
                                   ? fs::path(options_.tiles.graph).parent_path() /
                                         (fs::path(options_.tiles.graph).stem().string() + ".tiles")
                                   : fs::path(options_.out_dir);
    }
    if (options_.lines_per_task != 1 && options_.format != "slurm")
      throw Error(ExitCode::bad_command_line, "--lines-per-task is for --format slurm", "--lines-per-task");
    if (options_.format == "slurm" && slurm_commands_path(options_.output.path) == fs::path(options_.output.path))
      throw Error(ExitCode::bad_command_line, "the slurm script's commands file would overwrite it: name it otherwise",
                  options_.output.path);
    options_.output.check_writable();
  }

  int run() override {
    const std::vector<BatchScene> scenes =
        options_.scenes.empty() ? std::vector<BatchScene>{} : load_batch_scenes(options_.scenes, options_.out_dir);
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
    std::vector<PlannedBake> tiles;
    if (!options_.tiles.graph.empty()) {
      if (!fs::is_regular_file(options_.tiles.graph))
        throw Error(ExitCode::io_failure, "graph not found", options_.tiles.graph.string());
      tiles = plan_synthesis_tiles(options_.tiles, options_.program);
      regeneration.inputs.push_back(options_.tiles.graph);
    }
    std::set<fs::path> folders;
    for (const BatchAsset& a : batch) folders.insert(a.file.parent_path());
    if (!tiles.empty()) folders.insert(options_.tiles.out_dir);
    for (const fs::path& folder : folders) {
      std::error_code ec;
      if (!folder.empty()) fs::create_directories(folder, ec);
      if (ec) throw Error(ExitCode::io_failure, "cannot create the output folder: " + ec.message(), folder.string());
    }
    bakes.insert(bakes.end(), tiles.begin(), tiles.end());
    write(bakes, regeneration);
    size_t shared = 0;
    for (const BatchAsset& a : batch) {
      std::set<std::string> by;
      for (const BatchUse& u : a.uses) by.insert(u.scene);
      shared += by.size() > 1;
    }
    const size_t assets = bakes.size() - tiles.size();
    std::cout << "plan: wrote " << options_.output.path << " (" << options_.format;
    if (!scenes.empty())
      std::cout << ", " << assets << " asset" << (assets == 1 ? "" : "s") << " from " << scenes.size() << " scene"
                << (scenes.size() == 1 ? "" : "s") << ", " << shared << " shared by several scenes";
    if (!options_.tiles.graph.empty())
      std::cout << ", " << tiles.size() << " synthesis tile" << (tiles.size() == 1 ? "" : "s");
    std::cout << ")\n";
    const size_t tasks = slurm_task_count(bakes.size(), options_.lines_per_task);
    if (options_.format == "slurm" && tasks > kSlurmDefaultMaxArraySize - 1)
      std::cerr << "microbake: warning: " << tasks << " array tasks: Slurm's default MaxArraySize ("
                << kSlurmDefaultMaxArraySize << ") allows task ids up to " << kSlurmDefaultMaxArraySize - 1
                << "; raise it or use --lines-per-task "
                << (bakes.size() + kSlurmDefaultMaxArraySize - 2) / (kSlurmDefaultMaxArraySize - 1) << "\n";
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
    if (options_.lines_per_task != 1)
      words.insert(words.end(), {"--lines-per-task", std::to_string(options_.lines_per_task)});
    if (options_.tiles.graph.empty()) return words;
    // The tiles' synth command carries the same options: take them from it, minus its program, kind, graph, window
    // and output.
    const SynthesisTileRequest& t = options_.tiles;
    words.insert(words.end(), {"--synth", t.graph.string()});
    append_option(words, "--window", t.window.window);
    AssetRecipe recipe;
    recipe.kind = "synth";
    recipe.technique_values = t.technique_values;
    const std::vector<std::string> synth = asset_command(recipe, "", "", {});
    words.insert(words.end(), synth.begin() + 2, synth.end() - 2);
    append_option(words, "--jitter", t.window.jitter);
    if (t.window.no_correction) words.push_back("--no-correction");
    words.insert(words.end(), {"--tile", std::to_string(t.tile), "--tile-format", options_.tile_format});
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
      write_text(options_.output, slurm_script(bakes.size(), options_.lines_per_task, commands, fs::current_path()));
    }
  }

  struct Options {
    std::vector<std::string> scenes;
    OutputOption output;
    std::string format = "ninja";
    std::string out_dir;
    std::string program = "microbake";
    uint32_t lines_per_task = 1;
    SynthesisTileRequest tiles;
    std::string tile_format = "exr";
  } options_;
  SchemaOptions synth_schema_;
  CLI::App* app_ = nullptr;
};

}  // namespace

std::unique_ptr<Command> make_plan_command() { return std::make_unique<PlanCommand>(); }

}  // namespace mbk::cli
