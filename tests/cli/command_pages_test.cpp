// Every command has its page, and every page tells the truth about its command: for each command `microbake help`
// lists, docs/commands/<command>.md exists with the sections Synopsis, Description, Options, Examples and
// Exit status (and JSON output, naming its schema, when the command has --format json); its synopsis starts with
// `microbake <command>`; every option `microbake <command> --help` lists has a row in the page's option tables; every
// example of the help is among the page's examples; and the README's command table links the page. A page that names an
// option the command does not have fails too.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "tests/cli/shell_run.h"
#include "tests/scratch_dir.h"

namespace {
namespace fs = std::filesystem;
using mbk::test::file_text;
using mbk::test::run_shell;

const std::string kSourceDir = MICROBAKE_SOURCE_DIR;

// The long names ("--threads") and short-only names ("-q" when it has no long form) of the options a help text
// lists under "Options:", without -h/--help.
std::set<std::string> help_options(const std::string& help) {
  std::set<std::string> names;
  std::istringstream in(help.substr(help.find("\nOptions:\n") + 10));
  static const std::regex option_line(R"(^  (-[^ ]+))");
  for (std::string line; std::getline(in, line) && (line.empty() || line[0] == ' ');) {
    std::smatch m;
    if (!std::regex_search(line, m, option_line)) continue;
    std::string chosen;
    std::stringstream parts(m[1].str());
    for (std::string name; std::getline(parts, name, ',');)
      if (chosen.empty() || name.rfind("--", 0) == 0) chosen = name;
    if (chosen != "--help") names.insert(chosen);
  }
  return names;
}

// The "## " sections of a page, by heading, each with its text.
std::map<std::string, std::string> page_sections(const std::string& page) {
  std::map<std::string, std::string> sections;
  std::istringstream in(page);
  std::string current;
  bool in_code = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    if (!in_code && line.rfind("## ", 0) == 0) {
      current = line.substr(3);
      sections[current];
      continue;
    }
    if (!current.empty()) sections[current] += line + "\n";
  }
  return sections;
}

// The option names in the first cell of the rows of a page's option tables ("| `-o, --output FILE` | ..." ->
// "-o", "--output").
std::set<std::string> documented_options(const std::string& options_section) {
  std::set<std::string> names;
  static const std::regex row(R"(^\| `([^`]*)`)");
  static const std::regex name(R"((^|[ ,])(--?[a-z][a-z0-9-]*))");
  std::istringstream in(options_section);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    const std::string cell = m[1].str();
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), name); it != std::sregex_iterator(); ++it)
      names.insert((*it)[2].str());
  }
  return names;
}

TEST(CommandPages, EveryCommandHasAPageThatListsItsOptionsAndExamples) {
  const mbk::test::ScratchDir dir;
  const std::vector<std::string> commands = mbk::test::microbake_commands(MICROBAKE_EXE, dir.path());
  ASSERT_GE(commands.size(), 18u);
  const std::string readme = file_text(kSourceDir + "/README.md");
  for (const std::string& command : commands) {
    const fs::path page_path = fs::path(kSourceDir) / "docs/commands" / (command + ".md");
    ASSERT_TRUE(fs::is_regular_file(page_path)) << command << " has no page " << page_path;
    const std::string page = file_text(page_path);
    EXPECT_EQ(page.rfind("# `microbake " + command + "`", 0), 0u) << page_path << " must open with its command";
    const auto sections = page_sections(page);
    for (const char* heading : {"Synopsis", "Description", "Options", "Examples", "Exit status"})
      EXPECT_TRUE(sections.count(heading)) << page_path << " has no section '## " << heading << "'";
    if (sections.count("Synopsis"))
      EXPECT_NE(sections.at("Synopsis").find("microbake " + command), std::string::npos) << page_path;

    const std::string help = run_shell(std::string(MICROBAKE_EXE) + " " + command + " --help", dir.path()).out;
    const std::set<std::string> in_help = help_options(help);
    ASSERT_FALSE(in_help.empty()) << command;
    if (help.find("--format text|json") != std::string::npos) {
      EXPECT_TRUE(sections.count("JSON output")) << page_path << " has no section '## JSON output'";
      if (sections.count("JSON output"))
        EXPECT_NE(sections.at("JSON output").find("formats/schema/"), std::string::npos)
            << page_path << "'s JSON output names no schema";
    }
    const std::set<std::string> in_page = documented_options(sections.count("Options") ? sections.at("Options") : "");
    for (const std::string& option : in_help)
      EXPECT_TRUE(in_page.count(option)) << command << " " << option << " has no row in " << page_path;
    for (const std::string& option : in_page) {
      if (option.rfind("--", 0) != 0) continue;
      EXPECT_TRUE(in_help.count(option)) << page_path << " documents " << option << ", which `microbake " << command
                                         << " --help` does not list";
    }

    std::istringstream help_lines(help.substr(help.rfind("\nExample")));
    const std::string& examples = sections.count("Examples") ? sections.at("Examples") : std::string();
    for (std::string line; std::getline(help_lines, line);) {
      if (line.rfind("  microbake ", 0) != 0) continue;
      EXPECT_NE(examples.find(line.substr(2)), std::string::npos)
          << page_path << " lacks the help's example: " << line.substr(2);
    }

    EXPECT_NE(readme.find("](docs/commands/" + command + ".md)"), std::string::npos)
        << "README.md's command table does not link " << page_path;
  }
}

}  // namespace
