// The one error channel of microbake: an error carries its exit code (docs/ARCHITECTURE.md, "Errors") and where it
// happened (a file, a pixel, a section, a JSON path). Helpers throw; only cli/main.cpp turns errors into
// exit codes and the one-line message `microbake: error: <what> (<where>)`.
#pragma once

#include <stdexcept>
#include <string>

namespace mbk {

// Exit codes, the same for every command.
enum class ExitCode : int {
  success = 0,
  bad_command_line = 1,
  io_failure = 2,        // missing file, unwritable output
  invalid_input = 3,     // unreadable image, non-normal data, malformed JSON, corrupt asset
  runtime_failure = 4,   // runtime or numerical failure
  unsupported = 5,       // e.g. an asset from a newer major format version
  difference_found = 6,  // `compare` found a difference above the given threshold
};

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, std::string what, std::string where = {})
      : std::runtime_error(std::move(what)), code_(code), where_(std::move(where)) {}
  ExitCode code() const { return code_; }
  const std::string& where() const { return where_; }
  // "what (where)", or "what" when there is no location.
  std::string message() const { return where_.empty() ? what() : std::string(what()) + " (" + where_ + ")"; }

 private:
  ExitCode code_;
  std::string where_;
};

}  // namespace mbk
