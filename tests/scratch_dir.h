// The one scratch folder of the test suites: a fresh, empty folder under the system temporary folder, named
// after the running test (and a label, the process id and a counter, so that parallel ctest runs and several
// folders in one test never collide), removed with everything in it when it goes out of scope.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <string>

namespace mbk::test {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& label = "") {
    static std::atomic<int> counter{0};
    std::string name = "microbake";
    if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
      name += "_" + std::string(info->test_suite_name()) + "_" + info->name();
    if (!label.empty()) name += "_" + label;
    name += "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised test names contain '/'
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;  // never throw from a destructor; a leftover folder is harmless
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace mbk::test
