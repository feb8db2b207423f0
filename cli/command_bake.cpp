// `microbake bake SCENE [--out-dir DIR]`: bakes exactly the assets the scene's effects call for, each
// once even when several materials share it (libbake/scene/bake_plan.h), into the asset folder (default
// <scene folder>/<scene stem>.assets, where `render` looks). An existing file that records the same input
// content hashes, conventions, repair policy and parameters is skipped; any other is rebuilt
// (libbake/scene/asset_freshness.h). Prints what it baked, rebuilt and skipped, and why.
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "formats/error.h"
#include "libbake/scene/asset_freshness.h"
#include "libbake/scene/bake_plan.h"

namespace mbk::cli {
namespace {

// "bumpy:mip, stone:mip": which material's effect needs the asset.
std::string uses_text(const PlannedAsset& a) {
  std::string s;
  for (const auto& u : a.uses) s += (s.empty() ? "" : ", ") + u.material + ":" + u.effect;
  return s;
}

class BakeCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("SCENE", options_.scene, "Scene file (JSON)")->required();
    app.add_option("--out-dir", options_.out_dir,
                   "Asset folder (default: <scene folder>/<scene stem>.assets, where 'render' looks)")
        ->type_name("DIR");
    add_format_option(app, options_.format);
    add_run_options(app, options_.run);
  }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    const Scene scene = load_scene(options_.scene);
    const std::vector<PlannedAsset> plan = plan_assets(scene);
    const std::filesystem::path folder =
        options_.out_dir.empty() ? default_asset_folder(scene) : std::filesystem::path(options_.out_dir);
    const bool text = options_.format == OutputFormat::text && !options_.run.quiet;
    nlohmann::json report = {
        {"scene", options_.scene}, {"asset_folder", folder.string()}, {"assets", nlohmann::json::array()}};
    for (const PlannedAsset& a : plan)
      for (const BakeInput& in : a.recipe.inputs) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(in.path, ec))
          throw Error(ExitCode::io_failure,
                      std::string(in.normal_map ? "normal map" : "input file") + " of material '" +
                          a.uses.front().material + "' (effect '" + a.uses.front().effect + "') not found",
                      in.path.string());
      }
    if (plan.empty()) {
      if (text)
        std::cout << "nothing to bake: no material in " << options_.scene << " names an effect that needs an asset\n";
    } else {
      std::error_code ec;
      std::filesystem::create_directories(folder, ec);
      if (ec) throw Error(ExitCode::io_failure, "cannot create the asset folder: " + ec.message(), folder.string());
      if (text) std::cout << "asset folder: " << folder.string() << "\n";
    }
    progress.start("bake", plan.size());
    for (const PlannedAsset& a : plan) {
      const std::filesystem::path file = folder / a.file_name;
      const AssetFreshness fresh = check_asset_freshness(a, file);
      std::string action = "skipped";
      if (fresh.state != AssetState::up_to_date) {
        // The bar counts assets; a long bake inside one asset stays quiet.
        OutputOption{file.string()}.write_asset(bake_from_scene(a));
        action = fresh.state == AssetState::missing ? "baked" : "rebuilt";
      }
      progress.advance();
      nlohmann::json uses = nlohmann::json::array();
      for (const auto& u : a.uses) uses.push_back({{"material", u.material}, {"effect", u.effect}});
      nlohmann::json inputs = nlohmann::json::array();
      for (const BakeInput& in : a.recipe.inputs) inputs.push_back(in.path.string());
      report["assets"].push_back({{"file", file.string()},
                                  {"kind", a.recipe.kind},
                                  {"inputs", inputs},
                                  {"action", action},
                                  {"reason", fresh.reason},
                                  {"uses", uses}});
      if (text)
        std::cout << action << " " << a.file_name << " (" << a.recipe.kind << ", used by " << uses_text(a)
                  << "): " << fresh.reason << "\n";
    }
    progress.finish();
    if (options_.format == OutputFormat::json) std::cout << report.dump(2) << "\n";
    return 0;
  }

 private:
  // The library's checks of bake options are worded for the command line (Error bad_command_line); here the
  // options came from the scene file, so a refused one is invalid input at the effect that set it.
  AssetWriter bake_from_scene(const PlannedAsset& a) const {
    try {
      return a.recipe.bake(Progress::silent());
    } catch (const Error& e) {
      if (e.code() != ExitCode::bad_command_line) throw;
      const AssetUse& use = a.uses.front();
      throw Error(ExitCode::invalid_input, e.what() + std::string(" (an option of effect '") + use.effect + "')",
                  options_.scene + ": " + json_child_path(json_child_path("materials", use.material), "effects"));
    }
  }

  struct Options {
    std::string scene;
    std::string out_dir;
    OutputFormat format = OutputFormat::text;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_bake_command() { return std::make_unique<BakeCommand>(); }

}  // namespace mbk::cli
