// `microbake bake SCENE... [--out-dir DIR] [--jobs N] [--keep-going] [--prune] [--dry-run] [--format text|json]`:
// bakes exactly the assets the scenes call for (libbake/scene/batch_plan.h), each once even when several materials
// or scenes share it, into each scene's asset folder (default <scene folder>/<scene stem>.assets, where `render`
// looks; --out-dir: one folder for all). An existing file that records the same input content hashes, conventions,
// repair policy and parameters is skipped; any other is rebuilt (libbake/scene/asset_freshness.h). --jobs bakes
// independent assets side by side, sharing the --threads budget (the bytes do not depend on it). --keep-going bakes
// everything it can and fails at the end; --prune removes the assets in the asset folders that no scene calls for.
// The report (text, or JSON with --format json, printed also on failure) lists every asset with its status
// (docs/commands/bake.md "Bake report").
#include <algorithm>
#include <atomic>
#include <chrono>
#include <iostream>
#include <mutex>
#include <regex>
#include <set>
#include <thread>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/parameter_options.h"
#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/scene/asset_freshness.h"
#include "libbake/scene/batch_plan.h"

namespace mbk::cli {
namespace {

namespace fs = std::filesystem;

// The report's format name and version (docs/commands/bake.md "Bake report", formats/schema/bake.schema.json); a
// change of its fields changes the version.
constexpr const char* kReportSchema = "microbake.bake/1";

struct AssetOutcome {
  std::string status;  // baked | skipped | failed | pending (--dry-run: would be baked); queued while baking
  std::string reason;
  bool replaces_a_file = false;  // a stale file was there (text: "rebuilt")
  double seconds = 0;
  std::optional<Error> error;
};

// "a:mip, b:glints" (one scene) or "s.json a:mip, t.json b:glints" (several).
std::string uses_text(const BatchAsset& a, bool several_scenes) {
  std::string s;
  for (const BatchUse& u : a.uses)
    s += (s.empty() ? "" : ", ") + (several_scenes ? u.scene + " " : "") + u.material + ":" + u.effect;
  return s;
}

uint64_t size_or_zero(const fs::path& file) {
  std::error_code ec;
  const uint64_t bytes = fs::file_size(file, ec);
  return ec ? 0 : bytes;
}

// Asset files as `plan` and `bake` name them: <stem>.<kind>.<16 hex>.mbk.
bool is_planned_asset_name(const std::string& name) {
  static const std::regex pattern(R"([A-Za-z0-9_-]+\.[a-z]+\.[0-9a-f]{16}\.mbk)");
  return std::regex_match(name, pattern);
}

class BakeCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("SCENE", options_.scenes, "Scene files (JSON); an asset several of them call for is baked once")
        ->required();
    app.add_option("--out-dir", options_.out_dir,
                   "Asset folder of every scene (default: <scene folder>/<scene stem>.assets, where 'render' looks)")
        ->type_name("DIR");
    add_parameter_option(app,
                         integer_option("--jobs", 1, 1024, 1,
                                        "Assets baked side by side, sharing the --threads budget (at most one job per "
                                        "thread); the files do not depend on it"),
                         options_.jobs);
    app.add_flag("--keep-going", options_.keep_going,
                 "Bake every asset it can after a failure; exit with the first failure's code at the end");
    app.add_flag("--prune", options_.prune,
                 "Remove asset files (<stem>.<kind>.<hash>.mbk) in the asset folders that none of the scenes calls "
                 "for any more, and list them");
    app.add_flag("--dry-run", options_.dry_run, "List what would be baked, skipped and pruned; write nothing");
    add_format_option(app, options_.format);
    add_run_options(app, options_.run);
  }

  int run() override {
    options_.run.apply();
    nlohmann::json report = {{"schema", kReportSchema},
                             {"scenes", options_.scenes},
                             {"dry_run", options_.dry_run},
                             {"assets", nlohmann::json::array()},
                             {"pruned", nlohmann::json::array()}};
    try {
      return bake_all(report);
    } catch (const Error& e) {
      report["error"] = {{"message", e.message()}, {"exit_code", int(e.code())}};
      if (options_.format == OutputFormat::json && !report_printed_) std::cout << report.dump(2) << "\n";
      throw;
    }
  }

 private:
  bool text() const { return options_.format == OutputFormat::text && !options_.run.quiet; }

  // Each asset's outcome before baking: failed (an input is missing), skipped (up to date), or queued (pending with
  // --dry-run) with the reason; returns the indices of those to bake.
  std::vector<size_t> check_freshness(const std::vector<BatchAsset>& batch, std::vector<AssetOutcome>& outcomes) const {
    std::vector<size_t> to_bake;
    for (size_t i = 0; i < batch.size(); ++i) {
      const BatchAsset& a = batch[i];
      if (a.file.empty()) {
        outcomes[i] = failure(a, Error(ExitCode::io_failure, a.missing_input + " not found"));
        continue;
      }
      const AssetFreshness fresh = check_asset_freshness(a.planned, a.file);
      outcomes[i].reason = fresh.reason;
      if (fresh.state == AssetState::up_to_date) {
        outcomes[i].status = "skipped";
      } else {
        outcomes[i].status = options_.dry_run ? "pending" : "queued";
        outcomes[i].replaces_a_file = fresh.state == AssetState::stale;
        to_bake.push_back(i);
      }
    }
    return to_bake;
  }

  // One report entry per asset (and, as text, one line): path, kind, status, reason, time, size, inputs, uses.
  void report_assets(const std::vector<BatchAsset>& batch, const std::vector<AssetOutcome>& outcomes, bool several,
                     nlohmann::json& report) const {
    for (size_t i = 0; i < batch.size(); ++i) {
      const BatchAsset& a = batch[i];
      const AssetOutcome& o = outcomes[i];
      nlohmann::json uses = nlohmann::json::array(), inputs = nlohmann::json::array();
      for (const BatchUse& u : a.uses)
        uses.push_back({{"scene", u.scene}, {"material", u.material}, {"effect", u.effect}});
      for (const BakeInput& in : a.planned.recipe.inputs) inputs.push_back(in.path.string());
      report["assets"].push_back({{"path", a.file.string()},
                                  {"kind", a.planned.recipe.kind},
                                  {"status", o.status},
                                  {"reason", o.reason},
                                  {"seconds", o.seconds},
                                  {"bytes", o.status == "baked" || o.status == "skipped" ? size_or_zero(a.file) : 0},
                                  {"inputs", inputs},
                                  {"uses", uses}});
      if (text())
        std::cout << (o.status == "pending"                      ? "would bake"
                      : o.status == "baked" && o.replaces_a_file ? "rebuilt"
                                                                 : o.status)
                  << " " << (a.file.empty() ? a.planned.recipe.kind + " asset" : a.file.filename().string()) << " ("
                  << a.planned.recipe.kind << ", used by " << uses_text(a, several) << "): " << o.reason << "\n";
    }
  }

  int bake_all(nlohmann::json& report) {
    const std::vector<BatchScene> scenes = load_batch_scenes(options_.scenes, options_.out_dir);
    const std::vector<BatchAsset> batch = plan_batch(scenes);
    std::vector<AssetOutcome> outcomes(batch.size());
    std::vector<size_t> to_bake = check_freshness(batch, outcomes);
    std::set<fs::path> folders;
    for (const BatchScene& s : scenes) folders.insert(s.asset_folder);
    const bool planned_everything = std::none_of(batch.begin(), batch.end(), [](auto& a) { return a.file.empty(); });
    if (!options_.keep_going && first_failure(outcomes)) to_bake.clear();
    if (!options_.dry_run) {
      for (const fs::path& folder : folders) {
        if (to_bake.empty()) break;
        std::error_code ec;
        fs::create_directories(folder, ec);
        if (ec) throw Error(ExitCode::io_failure, "cannot create the asset folder: " + ec.message(), folder.string());
      }
      bake_in_parallel(batch, to_bake, outcomes);
      for (AssetOutcome& o : outcomes)
        if (o.status == "queued") {
          o.status = "skipped";
          o.reason = "not baked: an earlier asset failed (--keep-going bakes the others)";
        }
    }
    std::vector<fs::path> pruned;
    if (options_.prune && planned_everything && !first_failure(outcomes)) pruned = prune(batch, folders);

    const bool several = scenes.size() > 1;
    if (text() && batch.empty()) std::cout << "nothing to bake: no material names an effect that needs an asset\n";
    if (text() && !batch.empty())
      for (const fs::path& folder : folders) std::cout << "asset folder: " << folder.string() << "\n";
    report_assets(batch, outcomes, several, report);
    for (const fs::path& p : pruned) {
      report["pruned"].push_back(p.string());
      if (text()) std::cout << (options_.dry_run ? "would prune " : "pruned ") << p.string() << "\n";
    }
    if (options_.prune && (!planned_everything || first_failure(outcomes)) && text())
      std::cout << "pruned nothing: not every asset could be planned and baked\n";
    size_t counts[3] = {0, 0, 0};
    for (const AssetOutcome& o : outcomes) counts[o.status == "failed" ? 2 : o.status == "skipped" ? 1 : 0]++;
    report["counts"] = {
        {options_.dry_run ? "pending" : "baked", counts[0]}, {"skipped", counts[1]}, {"failed", counts[2]}};
    if (const auto first = first_failure(outcomes))
      report["error"] = {{"message", outcomes[*first].error->message()},
                         {"exit_code", int(outcomes[*first].error->code())}};
    if (options_.format == OutputFormat::json) std::cout << report.dump(2) << "\n";
    report_printed_ = true;
    if (const auto first = first_failure(outcomes)) {
      const AssetOutcome& o = outcomes[*first];
      const size_t failed = counts[2];
      throw Error(o.error->code(),
                  failed == 1 ? std::string(o.error->what())
                              : std::to_string(failed) + " assets failed; the first: " + o.error->what(),
                  o.error->where());
    }
    return 0;
  }

  static std::optional<size_t> first_failure(const std::vector<AssetOutcome>& outcomes) {
    for (size_t i = 0; i < outcomes.size(); ++i)
      if (outcomes[i].status == "failed") return i;
    return std::nullopt;
  }

  // The error of one asset, naming the asset, its kind and who calls for it; an option refused by a baker's check
  // (worded for the command line) is invalid input at the effect that set it.
  AssetOutcome failure(const BatchAsset& a, const Error& e) const {
    const BatchUse& use = a.uses.front();
    const std::string asset = a.planned.recipe.kind + " asset" + (a.file.empty() ? "" : " " + a.file.string());
    AssetOutcome o;
    o.status = "failed";
    o.reason = e.message();
    const ExitCode code = e.code() == ExitCode::bad_command_line ? ExitCode::invalid_input : e.code();
    o.error = Error(code, "cannot bake the " + asset + " for " + use_text(use) + ": " + e.message(),
                    e.code() == ExitCode::bad_command_line
                        ? use.scene + ": " + json_child_path(json_child_path("materials", use.material), "effects")
                        : use.scene);
    return o;
  }

  // Bakes the chosen assets, `--jobs` at a time; each job gets an equal share of the thread budget. Without
  // --keep-going no new bake starts after a failure.
  void bake_in_parallel(const std::vector<BatchAsset>& batch, const std::vector<size_t>& to_bake,
                        std::vector<AssetOutcome>& outcomes) {
    Progress progress(options_.run.progress_mode());
    progress.start("bake", to_bake.size());
    const int budget = std::max(1, thread_count());
    const int jobs = std::max(1, std::min({int(options_.jobs), budget, int(std::max<size_t>(1, to_bake.size()))}));
    const int threads_per_job = std::max(1, budget / jobs);
    std::atomic<size_t> next{0};
    std::atomic<bool> stop{false};
    auto work = [&] {
      set_thread_count(threads_per_job);
      for (size_t k; !stop && (k = next++) < to_bake.size();) {
        const size_t i = to_bake[k];
        const auto start = std::chrono::steady_clock::now();
        try {
          OutputOption{batch[i].file.string()}.write_asset(batch[i].planned.recipe.bake(Progress::silent()));
          outcomes[i].status = "baked";
        } catch (const Error& e) {
          outcomes[i] = failure(batch[i], e);
          if (!options_.keep_going) stop = true;
        }
        outcomes[i].seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        progress.advance();
      }
    };
    if (jobs == 1) {
      work();
    } else {
      std::vector<std::thread> workers;
      for (int j = 0; j < jobs; ++j) workers.emplace_back(work);
      for (std::thread& t : workers) t.join();
    }
    set_thread_count(budget);
    progress.finish();
  }

  // Asset files in the folders that no asset of the batch is; removed unless --dry-run.
  std::vector<fs::path> prune(const std::vector<BatchAsset>& batch, const std::set<fs::path>& folders) const {
    std::set<fs::path> wanted;
    for (const BatchAsset& a : batch) wanted.insert(a.file.lexically_normal());
    std::vector<fs::path> stale;
    for (const fs::path& folder : folders) {
      std::error_code ec;
      for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path p = it->path();
        if (it->is_regular_file() && is_planned_asset_name(p.filename().string()) &&
            !wanted.count((folder / p.filename()).lexically_normal()))
          stale.push_back(p);
      }
    }
    std::sort(stale.begin(), stale.end());
    if (!options_.dry_run)
      for (const fs::path& p : stale) {
        std::error_code ec;
        if (!fs::remove(p, ec) && ec) throw Error(ExitCode::io_failure, "cannot remove: " + ec.message(), p.string());
      }
    return stale;
  }

  struct Options {
    std::vector<std::string> scenes;
    std::string out_dir;
    uint32_t jobs = 1;
    bool keep_going = false, prune = false, dry_run = false;
    OutputFormat format = OutputFormat::text;
    RunOptions run;
  } options_;
  bool report_printed_ = false;
};

}  // namespace

std::unique_ptr<Command> make_bake_command() { return std::make_unique<BakeCommand>(); }

}  // namespace mbk::cli
