// `microbake validate FILE... [--format text|json] [--warnings-as-errors]`: structure, checksums and each
// kind's invariants. Findings carry stable ids (formats/validation_messages.h). Exit 0 when every file is
// valid; otherwise the code of the first failing file: 2 unreadable (finding 1006, and an error line on
// stderr), 5 newer major version, 3 invalid. --format json prints one result per file, valid files included
// (schema "microbake.validate/1", formats/schema/validate.schema.json).
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "formats/atomic_file.h"
#include "formats/error.h"
#include "formats/validate.h"

namespace mbk::cli {
namespace {

class ValidateCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("FILE", options_.files, "Assets (.mbk) to check")->required();
    add_format_option(app, options_.format);
    app.add_flag("--warnings-as-errors", options_.warnings_as_errors, "Treat warnings as errors");
  }

  int run() override {
    int exit_code = 0;
    nlohmann::json results = nlohmann::json::array();
    for (const std::string& file : options_.files) {
      std::vector<Finding> findings;
      int file_code = 0;
      try {
        findings = validate_asset(read_file_bytes(file));
      } catch (const Error& e) {
        if (e.code() != ExitCode::io_failure) throw;
        std::cerr << "microbake: error: " << e.message() << "\n";
        findings.push_back(make_finding(msg::file_unreadable, e.what()));  // so that --format json lists it
        file_code = static_cast<int>(ExitCode::io_failure);
      }
      if (const Finding* f = first_error(findings, options_.warnings_as_errors); file_code == 0 && f)
        file_code = static_cast<int>(exit_code_for(*f));
      if (exit_code == 0) exit_code = file_code;
      nlohmann::json messages = nlohmann::json::array();
      for (const Finding& f : findings)
        messages.push_back(
            {{"id", f.id}, {"severity", severity_name(f.severity)}, {"message", f.message}, {"details", f.details}});
      results.push_back({{"file", file}, {"valid", file_code == 0}, {"exit_code", file_code}, {"messages", messages}});
      if (options_.format == OutputFormat::text && file_code != static_cast<int>(ExitCode::io_failure)) {
        std::cout << file << ": " << (file_code == 0 ? "valid" : "INVALID") << "\n";
        for (const Finding& f : findings)
          std::cout << "  " << severity_name(f.severity) << " " << f.id << ": " << f.message << "\n";
      }
    }
    if (options_.format == OutputFormat::json)
      std::cout
          << nlohmann::json{{"schema", "microbake.validate/1"}, {"valid", exit_code == 0}, {"files", results}}.dump(2)
          << "\n";
    return exit_code;
  }

 private:
  struct Options {
    std::vector<std::string> files;
    OutputFormat format = OutputFormat::text;
    bool warnings_as_errors = false;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_validate_command() { return std::make_unique<ValidateCommand>(); }

}  // namespace mbk::cli
