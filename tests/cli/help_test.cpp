// What `--help` teaches, for every command `microbake help` lists: `microbake help CMD` prints the same as
// `microbake CMD --help`; no parser internals (CLI11's ENUM, TEXT, {json->1}, "x in [a - b]") and no doubled word;
// positional arguments are named from one small set; and the help ends with one or two examples that work: all
// examples run, in a scratch folder beside a copy of examples/, in the order that makes each one's inputs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "tests/cli/shell_run.h"
#include "tests/scratch_dir.h"

namespace {
namespace fs = std::filesystem;

using mbk::test::ShellRun;

ShellRun run(const std::string& command, const fs::path& folder) { return mbk::test::run_shell(command, folder); }

std::string exe() { return MICROBAKE_EXE; }

std::vector<std::string> commands(const fs::path& folder) {
  const std::vector<std::string> names = mbk::test::microbake_commands(exe(), folder);
  EXPECT_FALSE(names.empty()) << "microbake help lists no command";
  return names;
}

// The example lines at the end of a help text.
std::vector<std::string> examples(const std::string& help) {
  std::vector<std::string> lines;
  const size_t at = help.rfind("\nExample");
  if (at == std::string::npos) return lines;
  std::istringstream in(help.substr(help.find('\n', at + 1) + 1));
  for (std::string line; std::getline(in, line);)
    if (line.rfind("  microbake ", 0) == 0) lines.push_back(line.substr(2));
  return lines;
}

TEST(Help, EveryCommandsHelpIsPlainAndEndsWithExamples) {
  const mbk::test::ScratchDir dir;
  const std::vector<std::string> names = commands(dir.path());
  ASSERT_EQ(names.size(), 18u);
  const std::regex internals(R"(ENUM|TEXT|FLOAT|UINT|\{[a-z0-9]+->|[0-9] - [0-9])");
  const std::regex doubled(R"(\b([A-Za-z]+) \1\b)");
  const std::regex positionals(R"(Usage: microbake [a-z]+ \[OPTIONS\]((?: \[?[A-Z]+(?:\.\.\.)?\]?)*)\n)");
  const std::set<std::string> allowed_positionals = {"INPUT",   "SCENE", "SCENE...", "[SCENE...]", "FILE",
                                                     "FILE...", "KIND",  "IMAGE",    "REFERENCE"};
  for (const std::string& name : names) {
    const ShellRun help = run(exe() + " " + name + " --help", dir.path());
    EXPECT_EQ(help.exit_code, 0) << name;
    EXPECT_EQ(run(exe() + " help " + name, dir.path()).out, help.out) << name;
    std::smatch m;
    EXPECT_FALSE(std::regex_search(help.out, m, internals)) << name << ": '" << m.str() << "' in\n" << help.out;
    EXPECT_FALSE(std::regex_search(help.out, m, doubled)) << name << ": '" << m.str() << "' in\n" << help.out;
    ASSERT_TRUE(std::regex_search(help.out, m, positionals)) << help.out;
    std::istringstream words(m[1].str());
    for (std::string word; words >> word;) EXPECT_TRUE(allowed_positionals.count(word)) << name << ": " << word;
    const auto lines = examples(help.out);
    EXPECT_GE(lines.size(), 1u) << name;
    EXPECT_LE(lines.size(), 2u) << name;
    for (const std::string& line : lines) EXPECT_EQ(line.rfind("microbake " + name + " ", 0), 0u) << line;
  }
}

TEST(Help, EveryExampleWorks) {
  const mbk::test::ScratchDir dir;
  // The examples' inputs: colour maps, graphs and scenes (not the result pictures).
  fs::create_directories(dir / "examples");
  for (const char* folder : {"colormaps", "graphs", "scenes"})
    fs::copy(fs::path(MICROBAKE_SOURCE_DIR) / "examples" / folder, dir / "examples" / folder,
             fs::copy_options::recursive);
  fs::copy(fs::path(MICROBAKE_SOURCE_DIR) / "examples" / "make_synth_exemplars.sh", dir / "examples");
  // The exemplars examples/graphs/chain.json names.
  ASSERT_EQ(run("MICROBAKE=" + exe() + " bash examples/make_synth_exemplars.sh", dir.path()).exit_code, 0);
  // Each command after the ones that make its inputs.
  const std::vector<std::string> order = {"gen",       "mip",    "lut",      "rmq",     "sh",    "vmf",
                                          "histogram", "crease", "colormap", "moments", "graph", "synth",
                                          "bake",      "plan",   "render",   "compare", "info",  "validate"};
  const std::vector<std::string> names = commands(dir.path());
  EXPECT_EQ(std::set<std::string>(order.begin(), order.end()), std::set<std::string>(names.begin(), names.end()));
  for (const std::string& name : order)
    for (const std::string& line : examples(run(exe() + " help " + name, dir.path()).out)) {
      const ShellRun r = run(exe() + line.substr(std::string("microbake").size()), dir.path());
      EXPECT_EQ(r.exit_code, 0) << line << "\n" << r.err;
    }
}

}  // namespace
