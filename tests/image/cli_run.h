// For the image and generator suites: reading back the files a test wrote into its scratch folder
// (tests/scratch_dir.h), and running the built CLI.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/file_contents.h"
#include "tests/scratch_dir.h"

namespace mbk::test {

// Runs the built CLI with `arguments` (already shell-quoted), stdout and stderr to files in `folder`;
// returns the exit code.
struct CliRun {
  int exit_code;
  std::string out, err;
};
inline CliRun run_cli(const std::string& arguments, const ScratchDir& folder) {
  const auto out = folder / "cli_stdout.txt", err = folder / "cli_stderr.txt";
  const std::string command = std::string(MICROBAKE_EXE) + " " + arguments + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, file_text(out), file_text(err)};
}

}  // namespace mbk::test
