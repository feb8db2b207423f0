// Running a shell command line in a folder for the CLI tests, with its exit code, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/file_contents.h"

namespace mbk::test {

struct ShellRun {
  int exit_code;  // 128 + the signal when a signal ended it
  std::string out, err;
};

// Runs `command` with `sh -c` in `folder`, stdin from /dev/null; stdout and stderr pass through files in `folder`.
inline ShellRun run_shell(const std::string& command, const std::filesystem::path& folder) {
  const std::filesystem::path out = folder / ".stdout", err = folder / ".stderr";
  const std::string full =
      "cd '" + folder.string() + "' && ( " + command + " ) </dev/null >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(full.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), file_text(out), file_text(err)};
}

// The command names `microbake help` lists under "Commands:" (`exe` is the microbake executable).
inline std::vector<std::string> microbake_commands(const std::string& exe, const std::filesystem::path& folder) {
  const ShellRun r = run_shell(exe + " help", folder);
  std::vector<std::string> names;
  const size_t at = r.out.find("Commands:\n");
  if (r.exit_code != 0 || at == std::string::npos) return names;
  std::istringstream in(r.out.substr(at + 10));
  for (std::string line; std::getline(in, line) && line.rfind("  ", 0) == 0;)
    names.push_back(line.substr(2, line.find(' ', 2) - 2));
  return names;
}

}  // namespace mbk::test
