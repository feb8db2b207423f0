// The files `microbake plan` writes (docs/commands/plan.md), each from the same list of planned bakes:
//   ninja     build.ninja: one edge per asset (its input files as dependencies, restat), plus a generator edge that
//             re-plans when a scene or any input changes, so a second `ninja` after an edit bakes only what changed
//             (a changed input or parameter gives a new content-addressed name);
//   make      a Makefile with the same edges (make remakes it the same way);
//   commands  one shell command per line, for `parallel --joblog J --resume-failed -a FILE`;
//   slurm     a job-array script (`sbatch FILE`: --array=1-N) whose task i runs line i of the commands file written
//             beside it (FILE with its extension replaced by .commands); with K lines per task, task i runs lines
//             (i-1)K+1 .. iK one after another and stops at the first that fails, so N commands need ceil(N/K) tasks.
// Paths are as the scenes resolve them from the folder where `plan` ran: run the tools from there (the Slurm script
// changes to it itself).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace mbk::cli {

struct PlannedBake {
  std::filesystem::path output;
  std::vector<std::filesystem::path> inputs;
  std::vector<std::string> command;  // argv
  std::string description;           // "mip bumps.mip.<hash>.mbk"
};

struct PlanRegeneration {
  std::vector<std::string> command;           // argv of the `microbake plan` that wrote the file
  std::vector<std::filesystem::path> inputs;  // the scenes and every input file
};

std::string ninja_file(const std::vector<PlannedBake>& bakes, const PlanRegeneration& plan,
                       const std::filesystem::path& self);
std::string make_file(const std::vector<PlannedBake>& bakes, const PlanRegeneration& plan,
                      const std::filesystem::path& self);
std::string commands_file(const std::vector<PlannedBake>& bakes);
// Slurm refuses array task ids >= MaxArraySize, whose default is 1001.
inline constexpr size_t kSlurmDefaultMaxArraySize = 1001;

// The array tasks of `commands` lines at `lines_per_task` each.
size_t slurm_task_count(size_t commands, size_t lines_per_task);

// `commands_file` is the commands file's path and `folder` the folder to run in, both absolute.
std::string slurm_script(size_t commands, size_t lines_per_task, const std::filesystem::path& commands_file,
                         const std::filesystem::path& folder);

// The commands file beside a Slurm script: FILE with its extension replaced by ".commands".
std::filesystem::path slurm_commands_path(const std::filesystem::path& script);

}  // namespace mbk::cli
