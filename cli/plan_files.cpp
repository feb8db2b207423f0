// The Ninja, Make, GNU parallel and Slurm files of `microbake plan` (see plan_files.h).
#include "cli/plan_files.h"

#include "formats/error.h"
#include "libbake/scene/asset_command.h"

namespace mbk::cli {
namespace {

// A path on a Ninja build line: $, space and : escaped with $.
std::string ninja_path(const std::filesystem::path& p) {
  std::string out;
  for (char c : p.string()) {
    if (c == '$' || c == ' ' || c == ':') out += '$';
    out += c;
  }
  return out;
}

// A Ninja variable's value: $ escaped.
std::string ninja_value(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '$' ? std::string("$$") : std::string(1, c);
  return out;
}

// A path in a Makefile's target or prerequisite list. Make cannot name files with ':', '%', '*', '?', '[' or
// whitespace other than a space portably; those are refused.
std::string make_path(const std::filesystem::path& p) {
  std::string out;
  for (char c : p.string()) {
    if (std::string_view(":%*?[\t\n\\").find(c) != std::string_view::npos)
      throw Error(ExitCode::bad_command_line, "a Makefile cannot name this path (use --format ninja or commands)",
                  p.string());
    if (c == ' ' || c == '#') out += '\\';
    out += c == '$' ? std::string("$$") : std::string(1, c);
  }
  return out;
}

// A recipe line: $ doubled for make.
std::string make_recipe(const std::string& line) {
  std::string out;
  for (char c : line) out += c == '$' ? std::string("$$") : std::string(1, c);
  return out;
}

const char* kHeader = "microbake plan (docs/commands/plan.md); paths are relative to the folder plan ran in";

}  // namespace

std::string ninja_file(const std::vector<PlannedBake>& bakes, const PlanRegeneration& plan,
                       const std::filesystem::path& self) {
  std::string s = std::string("# Written by ") + kHeader + ": run ninja there.\n" +
                  "# One edge per asset; a changed scene or input re-plans first (new content-addressed names).\n"
                  "ninja_required_version = 1.7\n\n"
                  "rule bake\n  command = $command\n  description = $description\n  restat = 1\n\n"
                  "rule plan\n  command = $command\n  description = re-planning: a scene or an input changed\n"
                  "  generator = 1\n  restat = 1\n\n";
  s += "build " + ninja_path(self) + ": plan";
  for (const auto& in : plan.inputs) s += " " + ninja_path(in);
  s += "\n  command = " + ninja_value(shell_command_line(plan.command)) + "\n\n";
  for (const PlannedBake& b : bakes) {
    s += "build " + ninja_path(b.output) + ": bake";
    for (const auto& in : b.inputs) s += " " + ninja_path(in);
    s += "\n  command = " + ninja_value(shell_command_line(b.command)) +
         "\n  description = " + ninja_value(b.description) + "\n";
  }
  return s;
}

std::string make_file(const std::vector<PlannedBake>& bakes, const PlanRegeneration& plan,
                      const std::filesystem::path& self) {
  std::string s = std::string("# Written by ") + kHeader + ": run make there.\n" +
                  "# One rule per asset; a changed scene or input re-plans first (new content-addressed names).\n\n"
                  ".PHONY: all\nall:";
  for (const PlannedBake& b : bakes) s += " " + make_path(b.output);
  s += "\n\n" + make_path(self) + ":";
  for (const auto& in : plan.inputs) s += " " + make_path(in);
  s += "\n\t" + make_recipe(shell_command_line(plan.command)) + "\n";
  for (const PlannedBake& b : bakes) {
    s += "\n" + make_path(b.output) + ":";
    for (const auto& in : b.inputs) s += " " + make_path(in);
    s += "\n\t@echo " + shell_quoted(b.description) + "\n\t@" + make_recipe(shell_command_line(b.command)) + "\n";
  }
  return s;
}

std::string commands_file(const std::vector<PlannedBake>& bakes) {
  std::string s;
  for (const PlannedBake& b : bakes) s += shell_command_line(b.command) + "\n";
  return s;
}

size_t slurm_task_count(size_t commands, size_t lines_per_task) {
  return (commands + lines_per_task - 1) / lines_per_task;
}

std::string slurm_script(size_t commands, size_t lines_per_task, const std::filesystem::path& commands_file,
                         const std::filesystem::path& folder) {
  const size_t tasks = slurm_task_count(commands, lines_per_task);
  const std::string array = tasks == 0 ? "0-0" : "1-" + std::to_string(tasks);
  return "#!/bin/bash\n"
         "# Written by " +
         std::string(kHeader) + ".\n" +
         "# A Slurm job array: task i runs lines (i-1)*K+1 .. i*K of the commands file, K = lines_per_task, one after\n"
         "# another, stopping at the first that fails. Submit with: sbatch THIS_FILE\n"
         "#SBATCH --job-name=microbake-bake\n"
         "#SBATCH --array=" +
         array + "\n#SBATCH --chdir=" + folder.string() +
         "\n"
         "set -euo pipefail\n"
         "commands=" +
         shell_quoted(commands_file.string()) + "\nlines_per_task=" + std::to_string(lines_per_task) +
         "\n"
         "[ \"${SLURM_ARRAY_TASK_ID:-0}\" -ge 1 ] || exit 0  # an empty plan\n"
         "first=$(( (SLURM_ARRAY_TASK_ID - 1) * lines_per_task + 1 ))\n"
         "last=$(( first + lines_per_task - 1 ))\n"
         "while IFS= read -r line; do\n"
         "  bash -c \"$line\" || exit $?\n"
         "done < <(sed -n \"${first},${last}p\" \"$commands\")\n";
}

std::filesystem::path slurm_commands_path(const std::filesystem::path& script) {
  std::filesystem::path p = script;
  return p.replace_extension(".commands");
}

}  // namespace mbk::cli
