// microbake's entry point: the only table of commands, and the only place where errors become exit codes
// (docs/ARCHITECTURE.md, "Errors"). Every error is printed as one line `microbake: error: <what> (<where>)`.
#include <cstdio>
#include <iostream>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "formats/error.h"
#include "formats/version.h"

namespace mbk::cli {
namespace {

std::vector<CommandEntry> command_table() {
  return {
      {"info", "Print an asset's header, metadata and sections", make_info_command},
      {"validate", "Check assets' structure, checksums and invariants (exit 3 when invalid)", make_validate_command},
      {"gen", "Generate a procedural example normal map (bumps, brushed, scratches, flakes, leather, panels)",
       make_gen_command},
      {"mip", "Bake a normal map's MIP pyramid (asset kind mip)", make_mip_command},
      {"lut", "Bake an example's standardization LUTs for histogram-preserving glints (asset kind lut)",
       make_lut_command},
      {"rmq", "Bake an example's RMQ min/max table for glint range queries (asset kind rmq)", make_rmq_command},
      {"sh", "Bake a normal map's SH NDF pyramid for frequency-domain filtering (asset kind sh)", make_sh_command},
      {"vmf", "Bake a normal map's vMF mixture MIP maps by spherical EM (asset kind vmf)", make_vmf_command},
      {"colormap", "Bake a colour map prefiltered with Gaussians, indexed by (mean, sigma) (asset kind colormap)",
       make_colormap_command},
      {"moments",
       "Bake the MIP pyramid of (f, f^2) of a driver image for footprint mean and variance (asset kind "
       "moments)",
       make_moments_command},
      {"crease", "Bake a normal map with discontinuity curves into crisp-crease maps (asset kind crease)",
       make_crease_command},
      {"graph", "Analyse an exemplar graph for multiscale texture synthesis (asset kind graph)", make_graph_command},
      {"synth", "Synthesize a window of a multiscale texture from an analysed exemplar graph", make_synth_command},
      {"bake", "Bake the assets a scene's effects need, skipping up-to-date ones", make_bake_command},
      {"render", "Render a scene with the reference shader evaluator (or its brute-force --reference)",
       make_render_command},
      {"compare", "Error metrics between two images (RMSE, relative MSE, PSNR; exit 6 above --max-rmse)",
       make_compare_command},
  };
}

// An empty value is never a number, a path or a choice: CLI11 would read "" as 0 for numbers.
void refuse_empty_values(CLI::App& sub) {
  const CLI::Validator non_empty([](std::string& value) { return value.empty() ? "an empty value" : std::string(); },
                                 "", "non-empty");
  for (CLI::Option* option : sub.get_options())
    if (option->get_expected_min() > 0) option->check(non_empty);
}

int report(const std::string& message, ExitCode code) {
  std::fprintf(stderr, "microbake: error: %s\n", message.c_str());
  return static_cast<int>(code);
}

}  // namespace

int main_impl(int argc, char** argv) {
  CLI::App app{
      "microbake: bakes example normal maps into versioned .mbk assets and renders what they mean.\n"
      "Exit codes: 0 success, 1 bad command line, 2 I/O failure, 3 invalid input, 4 runtime failure,\n"
      "5 unsupported, 6 difference above threshold (compare).",
      "microbake"};
  app.set_version_flag("--version", "microbake " + microbake_version());
  app.require_subcommand(1);
  auto table = command_table();
  std::vector<std::unique_ptr<Command>> commands;
  std::vector<CLI::App*> subcommands;
  for (const auto& entry : table) {
    commands.push_back(entry.make());
    CLI::App* sub = app.add_subcommand(entry.name, entry.summary);
    commands.back()->add_options(*sub);
    refuse_empty_values(*sub);
    subcommands.push_back(sub);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    std::string where = "see 'microbake --help'";
    for (auto* sub : subcommands)
      if (sub->parsed()) where = "see 'microbake " + sub->get_name() + " --help'";
    return report(what + " (" + where + ")", ExitCode::bad_command_line);
  }
  // Every error names where it happened; one that no helper located is placed in the command (a command-line
  // mistake: in its options, pointing at its help).
  std::string command = "microbake";
  for (auto* sub : subcommands)
    if (sub->parsed()) command = "microbake " + sub->get_name();
  auto located = [&](const Error& e) {
    if (!e.where().empty()) return e;
    return Error(e.code(), e.what(), e.code() == ExitCode::bad_command_line ? "see '" + command + " --help'" : command);
  };
  try {
    for (size_t i = 0; i < subcommands.size(); ++i) {
      if (!subcommands[i]->parsed()) continue;
      commands[i]->check();
      return commands[i]->run();
    }
    return report("no command given (see 'microbake --help')", ExitCode::bad_command_line);
  } catch (const Error& e) {
    const Error where_known = located(e);
    return report(where_known.message(), where_known.code());
  } catch (const std::bad_alloc&) {
    return report("out of memory (" + command + ")", ExitCode::runtime_failure);
  } catch (const std::exception& e) {
    return report(std::string("internal error: ") + e.what() + " (" + command + ")", ExitCode::runtime_failure);
  }
}

}  // namespace mbk::cli

int main(int argc, char** argv) { return mbk::cli::main_impl(argc, argv); }
