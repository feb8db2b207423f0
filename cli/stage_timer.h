// Wall-clock times of a command's stages (load, bake, write) for its summary line: lap() returns the
// seconds since the previous lap (or since construction).
#pragma once

#include <chrono>

namespace mbk::cli {

class StageTimer {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace mbk::cli
