// Warnings for the user from library code that went on after a guess (a normal map whose convention it could not
// decide, or that contradicts the one asked for). libbake never prints: it hands each warning, one line saying what
// and where, to the handler the program installed. The CLI's prints `microbake: warning: <what> (<where>)` on
// stderr, each distinct line once per run, and none under --quiet (cli/common_options.h). Without a handler,
// warnings are dropped. Thread-safe.
#pragma once

#include <functional>
#include <string>

namespace mbk {

using WarningHandler = std::function<void(const std::string& what, const std::string& where)>;

// Installs `handler` (an empty one drops warnings) and returns the one it replaces.
WarningHandler set_warning_handler(WarningHandler handler);

void warn(const std::string& what, const std::string& where);

}  // namespace mbk
