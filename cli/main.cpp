// microbake's entry point: the only table of commands, and the only place where errors become exit codes
// (docs/ARCHITECTURE.md, "Errors"). Every error is printed as one line `microbake: error: <what> (<where>)`.
#include <cctype>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "cli/help_formatter.h"
#include "cli/nearest_name.h"
#include "formats/error.h"
#include "formats/version.h"

namespace mbk::cli {
namespace {

std::vector<CommandEntry> command_table() {
  return {
      {"info",
       "Print an asset's header, metadata and sections",
       make_info_command,
       {"microbake info bumps_mip.mbk", "microbake info bumps_sh.mbk --format json"}},
      {"validate",
       "Check assets' structure, checksums and invariants (exit 3 when invalid)",
       make_validate_command,
       {"microbake validate bumps_mip.mbk bumps_sh.mbk", "microbake validate --format json bumps_vmf.mbk"}},
      {"gen",
       "Generate a procedural example normal map (bumps, brushed, scratches, flakes, leather, panels)",
       make_gen_command,
       {"microbake gen bumps --size 256 -o bumps.png",
        "microbake gen panels --size 256 -o panels.png --creases panels.json"}},
      {"mip",
       "Bake a normal map's MIP pyramid (asset kind mip)",
       make_mip_command,
       {"microbake mip bumps.png -o bumps_mip.mbk"}},
      {"lut",
       "Bake an example's standardization LUTs for histogram-preserving glints (asset kind lut)",
       make_lut_command,
       {"microbake lut bumps.png --size 128 -o bumps_lut.mbk"}},
      {"rmq",
       "Bake an example's RMQ min/max table for glint range queries (asset kind rmq)",
       make_rmq_command,
       {"microbake rmq bumps.png --patch 64 --bits 8 -o bumps_rmq.mbk"}},
      {"sh",
       "Bake a normal map's SH NDF pyramid for frequency-domain filtering (asset kind sh)",
       make_sh_command,
       {"microbake sh bumps.png --order 8 --window hann -o bumps_sh.mbk"}},
      {"vmf",
       "Bake a normal map's vMF mixture MIP maps by spherical EM (asset kind vmf)",
       make_vmf_command,
       {"microbake vmf bumps.png --lobes 3 --tolerance 1e-4 -o bumps_vmf.mbk"}},
      {"histogram",
       "Bake a normal map's adaptive bins and its binned P-NDF of any footprint: a neural histogram trained on the CPU "
       "(asset kind neural_histogram, the default) or exact per-bin integral images (asset kind histogram; tables "
       "above 4 GiB are refused, the neural bake trains on one)",
       make_histogram_command,
       {"microbake histogram bumps.png --iterations 300 -o bumps_neural.mbk",
        "microbake histogram bumps.png --method exact --theta-bins 6 --phi-bins 16 -o bumps_histogram.mbk"}},
      {"colormap",
       "Bake a colour map prefiltered with Gaussians, indexed by (mean, sigma) (asset kind colormap)",
       make_colormap_command,
       {"microbake colormap examples/colormaps/terrain.json --size 256x64 -o terrain.mbk"}},
      {"moments",
       "Bake the MIP pyramid of (f, f^2) of a driver image for footprint mean and variance (asset kind "
       "moments)",
       make_moments_command,
       {"microbake moments bumps.png --channel 2 -o bumps_moments.mbk"}},
      {"crease",
       "Bake a normal map with discontinuity curves into crisp-crease maps (asset kind crease)",
       make_crease_command,
       {"microbake crease panels.png --curves panels.json -o panels_crease.mbk"}},
      {"graph",
       "Analyse an exemplar graph for multiscale texture synthesis (asset kind graph)",
       make_graph_command,
       {"microbake graph examples/graphs/chain.json -o chain.mbk"}},
      {"synth",
       "Synthesize a window of a multiscale texture from an analysed exemplar graph",
       make_synth_command,
       {"microbake synth chain.mbk --level 8 --window 0,0,256,256 -o chain.png"}},
      {"bake",
       "Bake the assets a scene's effects need, skipping up-to-date ones",
       make_bake_command,
       {"microbake bake examples/scenes/colormap.json --out-dir colormap_assets"}},
      {"plan",
       "Write every asset the scenes need (or a synthesis window's tiles) as one command each, for ninja, make, GNU "
       "parallel or Slurm",
       make_plan_command,
       {"microbake plan examples/scenes/colormap.json --out-dir colormap_assets -o build.ninja",
        "microbake plan examples/scenes/colormap.json --out-dir colormap_assets --format commands -o bake.commands"}},
      {"render",
       "Render a scene with the reference shader evaluator (or its brute-force --reference)",
       make_render_command,
       {"microbake render examples/scenes/colormap.json --assets colormap_assets -o colormap.exr",
        "microbake render examples/scenes/colormap.json --reference 2 -o colormap_reference.exr"}},
      {"compare",
       "Error metrics between two images (RMSE, relative MSE, PSNR; exit 6 above --max-rmse)",
       make_compare_command,
       {"microbake compare colormap.exr colormap_reference.exr --max-rmse 0.05"}},
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

std::string help_footer(const std::vector<std::string>& examples) {
  std::string footer = examples.size() == 1 ? "Example:" : "Examples:";
  for (const std::string& e : examples) footer += "\n  " + e;
  return footer + "\n";
}

// "unknown command 'mipp'; did you mean 'mip'?" or, with nothing close, the list of commands.
std::string unknown_command(const std::string& typed, const std::vector<CommandEntry>& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.push_back(entry.name);
  const std::string near = nearest_name(typed, names);
  std::string list;
  for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
  return "unknown command '" + typed + "'" +
         (near.empty() ? " (commands: " + list + ")" : "; did you mean '" + near + "'?");
}

// The first argument after the command that looks like an option ("--thread", "-x", "--thread=2") and is none of
// the command's, as "unknown option '--thread'; did you mean '--threads'?"; "" when every option is known. Values
// such as "-5,0,8,8" or "-0.5" are not options.
std::string unknown_option(const CLI::App& sub, const std::vector<std::string>& arguments) {
  for (const std::string& argument : arguments) {
    if (argument == "--") break;
    const bool long_name = argument.size() > 2 && argument.compare(0, 2, "--") == 0 && std::isalpha(argument[2]);
    const bool short_name = argument.size() > 1 && argument[0] == '-' && std::isalpha(argument[1]);
    if (!long_name && !short_name) continue;
    const std::string name = long_name ? argument.substr(0, argument.find('=')) : argument.substr(0, 2);
    if (sub.get_option_no_throw(name)) continue;
    std::vector<std::string> names;
    for (const CLI::Option* option : sub.get_options())
      for (const std::string& known : option->get_lnames()) names.push_back("--" + known);
    const std::string near = nearest_name(name, names);
    return "unknown option '" + name + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?");
  }
  return "";
}

CLI::App* find_command(const std::vector<CLI::App*>& subcommands, const std::string& name) {
  for (auto* sub : subcommands)
    if (sub->get_name() == name) return sub;
  return nullptr;
}

// What is answered before CLI11 parses: `microbake help [COMMAND]`, no arguments, and a first argument that is no
// command nor option (CLI11 would print the main help for `nosuchcommand --help` and only "A subcommand is
// required" for `mipp x`). The exit code, or nothing when CLI11 should parse.
std::optional<int> answer_before_parsing(const CLI::App& app, const std::vector<CLI::App*>& subcommands,
                                         const std::vector<std::string>& arguments,
                                         const std::vector<CommandEntry>& table) {
  if (!arguments.empty() && arguments[0] == "help") {
    if (arguments.size() > 2)
      return report("help takes one command (see 'microbake help')", ExitCode::bad_command_line);
    if (arguments.size() == 1) {
      std::cout << app.help();
      return 0;
    }
    if (const CLI::App* sub = find_command(subcommands, arguments[1])) {
      std::cout << sub->help("microbake");
      return 0;
    }
    return report(unknown_command(arguments[1], table) + " (see 'microbake help')", ExitCode::bad_command_line);
  }
  if (!arguments.empty() && arguments[0].compare(0, 1, "-") != 0 && !find_command(subcommands, arguments[0]))
    return report(unknown_command(arguments[0], table) + " (see 'microbake help')", ExitCode::bad_command_line);
  if (arguments.empty()) return report("no command given (see 'microbake help')", ExitCode::bad_command_line);
  return std::nullopt;
}

// Runs the parsed command, turning every failure into its one-line message and exit code.
int run_parsed_command(const std::vector<CLI::App*>& subcommands,
                       const std::vector<std::unique_ptr<Command>>& commands) {
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
}  // namespace

int main_impl(int argc, char** argv) {
  CLI::App app{
      "microbake: bakes example normal maps into versioned .mbk assets and renders what they mean.\n"
      "Exit codes: 0 success, 1 bad command line, 2 I/O failure, 3 invalid input, 4 runtime failure,\n"
      "5 unsupported, 6 difference above threshold (compare).",
      "microbake"};
  app.formatter(std::make_shared<HelpFormatter>());
  app.set_version_flag("--version", "microbake " + microbake_version());
  app.require_subcommand(1);
  app.footer("Run 'microbake help COMMAND' or 'microbake COMMAND --help' for a command's options and examples.");
  const auto table = command_table();
  std::vector<std::unique_ptr<Command>> commands;
  std::vector<CLI::App*> subcommands;
  for (const auto& entry : table) {
    commands.push_back(entry.make());
    CLI::App* sub = app.add_subcommand(entry.name, entry.summary)->group("Commands");
    commands.back()->add_options(*sub);
    refuse_empty_values(*sub);
    sub->footer(help_footer(entry.examples));
    subcommands.push_back(sub);
  }
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (const std::optional<int> answered = answer_before_parsing(app, subcommands, arguments, table)) return *answered;
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
    std::string where = "see 'microbake help'";
    if (CLI::App* sub = find_command(subcommands, arguments[0])) {
      where = "see 'microbake " + sub->get_name() + " --help'";
      // An unknown option is the likeliest cause, whatever CLI11 noticed first (e.g. a required option it hid).
      if (const std::string unknown = unknown_option(*sub, {arguments.begin() + 1, arguments.end()}); !unknown.empty())
        what = unknown;
    }
    return report(what + " (" + where + ")", ExitCode::bad_command_line);
  }
  return run_parsed_command(subcommands, commands);
}

}  // namespace mbk::cli

int main(int argc, char** argv) { return mbk::cli::main_impl(argc, argv); }
