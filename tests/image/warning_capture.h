// For tests of code that raises warnings (libbake/core/warnings.h): collects them, as "<what> (<where>)" lines,
// while it lives, and puts the previous handler back afterwards.
#pragma once

#include <string>
#include <vector>

#include "libbake/core/warnings.h"

namespace mbk::test {

class WarningCapture {
 public:
  WarningCapture()
      : previous_(set_warning_handler([this](const std::string& what, const std::string& where) {
          lines_.push_back(what + " (" + where + ")");
        })) {}
  ~WarningCapture() { set_warning_handler(previous_); }
  WarningCapture(const WarningCapture&) = delete;
  WarningCapture& operator=(const WarningCapture&) = delete;

  const std::vector<std::string>& lines() const { return lines_; }
  void clear() { lines_.clear(); }

 private:
  std::vector<std::string> lines_;
  WarningHandler previous_;
};

}  // namespace mbk::test
