// CLI tests as data (tests/cli/cases.json): each case is a command line, the expected exit code, and what
// stdout/stderr must hold — text fragments (or, "stdout_lacks", must not), a regular expression, or a golden JSON file
// (tests/cli/golden/, rewritten when MICROBAKE_UPDATE_GOLDEN=1). Every failing case must print exactly one line
// `microbake: error: ...` on stderr, and the files a case lists under "absent" must not exist afterwards
// (no partial outputs). Placeholders: {exe} the built microbake, {tmp} this run's scratch folder, {src} the
// source tree. Commands run in the scratch folder, so relative paths name files there: a golden that shows paths
// or file offsets should use them, as their length would otherwise depend on the scratch folder's. "mask": a list
// of JSON pointers into the golden output whose values are replaced by "<masked>" in both the output and the
// golden before they are compared (for bytes that depend on library versions, e.g. a PNG encoder's hash);
// each must exist in the output. "skip_under_sanitizer": true skips a case in sanitized builds. The "setup"
// commands at the top of the file run once, before the cases.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tests/cli/shell_run.h"
#include "tests/scratch_dir.h"

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kCasesFile = fs::path(MICROBAKE_SOURCE_DIR) / "tests" / "cli" / "cases.json";

// Created on first use, removed when the process ends.
const fs::path& scratch_dir() {
  static const mbk::test::ScratchDir dir("cli");
  return dir.path();
}

std::string expand(std::string s) {
  const std::pair<std::string, std::string> subs[] = {
      {"{exe}", MICROBAKE_EXE}, {"{tmp}", scratch_dir().string()}, {"{src}", MICROBAKE_SOURCE_DIR}};
  for (const auto& [key, value] : subs)
    for (size_t pos; (pos = s.find(key)) != std::string::npos;) s.replace(pos, key.size(), value);
  return s;
}

using mbk::test::file_text;
using mbk::test::ShellRun;

ShellRun run_shell(const std::string& command) { return mbk::test::run_shell(command, scratch_dir()); }

json load_cases_file() { return json::parse(file_text(kCasesFile)); }

struct CliCase {
  std::string name;
  json spec;
};
// gtest prints a failing parameter with this instead of its bytes.
void PrintTo(const CliCase& c, std::ostream* os) { *os << c.name; }

std::vector<CliCase> load_cases() {
  std::vector<CliCase> cases;
  const json file = load_cases_file();
  for (const json& c : file.at("cases")) cases.push_back({c.at("name").get<std::string>(), c});
  return cases;
}

class CliEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    const json file = load_cases_file();
    for (const json& cmd : file.at("setup")) {
      ShellRun r = run_shell(expand(cmd.get<std::string>()));
      ASSERT_EQ(r.exit_code, 0) << "setup failed: " << cmd << "\n" << r.err;
    }
  }
};
const auto* const kEnvironment = ::testing::AddGlobalTestEnvironment(new CliEnvironment);

// Replaces this run's scratch path so that goldens do not depend on it.
std::string normalise(std::string s) {
  const std::string tmp = scratch_dir().string();
  for (size_t pos; (pos = s.find(tmp)) != std::string::npos;) s.replace(pos, tmp.size(), "{tmp}");
  return s;
}

// `j` with the value at each of the case's "mask" pointers replaced by "<masked>"; false when one is missing.
bool apply_mask(const json& spec, json& j, std::string* missing) {
  for (const auto& pointer : spec.value("mask", json::array())) {
    const json::json_pointer at(pointer.get<std::string>());
    if (!j.contains(at)) {
      *missing = pointer.get<std::string>();
      return false;
    }
    j[at] = "<masked>";
  }
  return true;
}

class CliCaseTest : public ::testing::TestWithParam<CliCase> {};

TEST_P(CliCaseTest, Behaves) {
  const json& c = GetParam().spec;
#ifdef MICROBAKE_SANITIZED
  // AddressSanitizer reserves terabytes of address space, so cases that limit memory cannot run under it.
  if (c.value("skip_under_sanitizer", false)) GTEST_SKIP() << "not meaningful under sanitizers";
#endif
  const std::string command = expand(c.at("command").get<std::string>());
  ShellRun r = run_shell(command);
  const int expected = c.at("exit").get<int>();
  EXPECT_EQ(r.exit_code, expected) << command << "\nstdout: " << r.out << "\nstderr: " << r.err;
  if (expected != 0 && c.value("one_line_error", true)) {
    static const std::regex one_line(R"(^microbake: error: [^\n]+\n$)");
    EXPECT_TRUE(std::regex_match(r.err, one_line)) << "stderr must be one error line, got: " << r.err;
  }
  for (const auto& frag : c.value("stdout_contains", json::array()))
    EXPECT_NE(r.out.find(expand(frag.get<std::string>())), std::string::npos) << "stdout lacks " << frag << ":\n"
                                                                              << r.out;
  for (const auto& frag : c.value("stderr_contains", json::array()))
    EXPECT_NE(r.err.find(expand(frag.get<std::string>())), std::string::npos) << "stderr lacks " << frag << ":\n"
                                                                              << r.err;
  for (const auto& frag : c.value("stdout_lacks", json::array()))
    EXPECT_EQ(r.out.find(expand(frag.get<std::string>())), std::string::npos) << "stdout holds " << frag << ":\n"
                                                                              << r.out;
  if (c.contains("stdout_regex")) {
    EXPECT_TRUE(std::regex_search(r.out, std::regex(c["stdout_regex"].get<std::string>()))) << r.out;
  }
  if (c.contains("stderr_regex")) {
    EXPECT_TRUE(std::regex_search(r.err, std::regex(c["stderr_regex"].get<std::string>()))) << r.err;
  }
  if (c.contains("stdout_golden")) {
    const fs::path golden =
        fs::path(MICROBAKE_SOURCE_DIR) / "tests" / "cli" / "golden" / c["stdout_golden"].get<std::string>();
    json actual = json::parse(normalise(r.out), nullptr, false);
    ASSERT_FALSE(actual.is_discarded()) << "stdout is not JSON: " << r.out;
    std::string missing;
    ASSERT_TRUE(apply_mask(c, actual, &missing)) << "mask " << missing << " is not in the output:\n" << r.out;
    if (const char* update = std::getenv("MICROBAKE_UPDATE_GOLDEN"); update && std::string(update) == "1") {
      std::ofstream(golden) << actual.dump(2) << "\n";
    } else {
      ASSERT_TRUE(fs::exists(golden)) << golden << " missing: run with MICROBAKE_UPDATE_GOLDEN=1 once and review it";
      json expected = json::parse(file_text(golden));
      ASSERT_TRUE(apply_mask(c, expected, &missing)) << "mask " << missing << " is not in " << golden;
      EXPECT_EQ(actual, expected) << "differs from " << golden << " (MICROBAKE_UPDATE_GOLDEN=1 rewrites it)";
    }
  }
  for (const auto& path : c.value("absent", json::array())) {
    const fs::path p = expand(path.get<std::string>());
    EXPECT_FALSE(fs::exists(p)) << p << " should not exist";
    for (const auto& e : fs::directory_iterator(p.parent_path()))
      EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << "left behind: " << e.path();
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, CliCaseTest, ::testing::ValuesIn(load_cases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
