// Running the built executable from a test without a shell: argv as given, in a folder, stdin from /dev/null,
// stdout and stderr captured, killed after a time limit; the result says how it ended (exit code or signal).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "tests/file_contents.h"

namespace mbk::test {

// Generous: the machine running CI may be busy; every run of the corpus takes well under 2 s.
constexpr int kCaseSeconds = 60;

struct Run {
  int exit_code = -1;  // -1 when killed by a signal
  int signal = 0;
  bool timed_out = false;
  std::string out, err;
};

// Starts the executable with `args` in `dir`, stdout and stderr going to `out` and `err` (relative to `dir`).
inline pid_t spawn_microbake(const std::vector<std::string>& args, const std::filesystem::path& dir,
                             const std::string& out = "/dev/null", const std::string& err = "/dev/null") {
  const pid_t child = ::fork();
  if (child == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int in = ::open("/dev/null", O_RDONLY);
    if (o < 0 || e < 0 || in < 0) ::_exit(127);
    ::dup2(in, 0);
    ::dup2(o, 1);
    ::dup2(e, 2);
    std::vector<char*> argv;
    std::string exe = MICROBAKE_EXE;
    argv.push_back(exe.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(exe.c_str(), argv.data());
    ::_exit(127);
  }
  return child;
}

// Waits for `child`, killing it after `seconds`; how it ended.
inline Run wait_for(pid_t child, int seconds = kCaseSeconds) {
  Run r;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  int status = 0;
  while (::waitpid(child, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      r.timed_out = true;
      ::kill(child, SIGKILL);
      ::waitpid(child, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

// Runs the executable with `args` in `dir`, without a shell, killing it after kCaseSeconds.
inline Run run_microbake(const std::vector<std::string>& args, const std::filesystem::path& dir) {
  Run r = wait_for(spawn_microbake(args, dir, ".run_stdout", ".run_stderr"));
  r.out = file_text(dir / ".run_stdout");
  r.err = file_text(dir / ".run_stderr");
  return r;
}

}  // namespace mbk::test
