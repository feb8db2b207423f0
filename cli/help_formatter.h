// How `--help` reads: an option shows the values it takes in words a user types ("--format text|json",
// "--order INT in [0, 256]", "-o,--output FILE"), never CLI11's internals; its default closes its description
// ("(default: 8)"); positional arguments are listed under "Arguments" by their upper-case names (INPUT, SCENE,
// FILE, ...), and the commands under "Commands".
#pragma once

#include <memory>

#include <CLI/CLI.hpp>

namespace mbk::cli {

class HelpFormatter : public CLI::Formatter {
 public:
  HelpFormatter();
  std::string make_option_opts(const CLI::Option* option) const override;
  std::string make_option_desc(const CLI::Option* option) const override;
};

}  // namespace mbk::cli
