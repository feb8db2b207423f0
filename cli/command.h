// The shape every command shares (KTX-Software's command_*.cpp pattern): a small class with an options
// struct, add_options() declaring them on its CLI11 subcommand, check() for rules across options, and
// run() returning the exit code. Commands throw mbk::Error; only main.cpp turns errors into exit codes.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace mbk::cli {

class Command {
 public:
  virtual ~Command() = default;
  virtual void add_options(CLI::App& app) = 0;
  // Cross-option rules; throw Error(ExitCode::bad_command_line) when violated.
  virtual void check() {}
  // Returns the exit code: 0 on success; validate returns 3 and compare 6 for their findings.
  virtual int run() = 0;
};

struct CommandEntry {
  std::string name;
  std::string summary;
  std::function<std::unique_ptr<Command>()> make;
  std::vector<std::string> examples;  // one or two real command lines, shown at the end of its help
};

// One factory per command file.
std::unique_ptr<Command> make_info_command();
std::unique_ptr<Command> make_validate_command();
std::unique_ptr<Command> make_gen_command();
std::unique_ptr<Command> make_mip_command();
std::unique_ptr<Command> make_lut_command();
std::unique_ptr<Command> make_rmq_command();
std::unique_ptr<Command> make_sh_command();
std::unique_ptr<Command> make_vmf_command();
std::unique_ptr<Command> make_histogram_command();
std::unique_ptr<Command> make_colormap_command();
std::unique_ptr<Command> make_moments_command();
std::unique_ptr<Command> make_crease_command();
std::unique_ptr<Command> make_graph_command();
std::unique_ptr<Command> make_synth_command();
std::unique_ptr<Command> make_bake_command();
std::unique_ptr<Command> make_plan_command();
std::unique_ptr<Command> make_render_command();
std::unique_ptr<Command> make_compare_command();

}  // namespace mbk::cli
