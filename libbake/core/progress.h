// Progress reporting for long work: a bar on stderr, shown on a terminal by default (`--progress auto`),
// always, or never; `--quiet` silences it. Thread-safe: workers call advance() from any thread.
// libbake functions that take long accept a Progress& and report through it; they never print themselves.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace mbk {

enum class ProgressMode { automatic, always, never };

class Progress {
 public:
  explicit Progress(ProgressMode mode = ProgressMode::never);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Starts a new task of `total` units (ends the previous one).
  void start(const std::string& label, uint64_t total);
  void advance(uint64_t units = 1);
  // A short text shown after the bar until the task ends (e.g. a training loss).
  void note(const std::string& text);
  // Ends the current task (clears the bar line).
  void finish();

  // A Progress that never prints, for tests and library callers.
  static Progress& silent();

 private:
  void draw(bool force);
  bool enabled_;
  std::string label_, note_;
  uint64_t total_ = 0;
  std::atomic<uint64_t> done_{0};
  std::mutex draw_mutex_;
  std::chrono::steady_clock::time_point last_draw_{};
  std::chrono::steady_clock::time_point started_{};
  bool drawn_ = false;
};

}  // namespace mbk
