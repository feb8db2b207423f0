// A text progress bar on stderr (see progress.h).
#include "libbake/core/progress.h"

#include <unistd.h>

#include <cstdio>

namespace mbk {

Progress::Progress(ProgressMode mode)
    : enabled_(mode == ProgressMode::always || (mode == ProgressMode::automatic && ::isatty(STDERR_FILENO))) {}

Progress::~Progress() { finish(); }

Progress& Progress::silent() {
  static Progress p(ProgressMode::never);
  return p;
}

void Progress::start(const std::string& label, uint64_t total) {
  finish();
  std::lock_guard lock(draw_mutex_);
  label_ = label;
  note_.clear();
  total_ = total;
  done_ = 0;
  started_ = std::chrono::steady_clock::now();
  last_draw_ = {};
}

void Progress::advance(uint64_t units) {
  done_.fetch_add(units, std::memory_order_relaxed);
  if (enabled_) draw(false);
}

void Progress::note(const std::string& text) {
  if (!enabled_) return;
  std::lock_guard lock(draw_mutex_);
  note_ = text;
}

void Progress::finish() {
  if (!enabled_) return;
  std::lock_guard lock(draw_mutex_);
  if (drawn_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
  }
}

void Progress::draw(bool force) {
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  auto now = std::chrono::steady_clock::now();
  if (!force && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  const uint64_t done = std::min<uint64_t>(done_.load(std::memory_order_relaxed), total_);
  const double frac = total_ ? double(done) / double(total_) : 1.0;
  const int width = 30, filled = int(frac * width);
  const double elapsed = std::chrono::duration<double>(now - started_).count();
  std::fprintf(stderr, "\r%s [%.*s%*s] %3d%% %.1fs%s%s", label_.c_str(), filled,
               "==============================", width - filled, "", int(frac * 100.0), elapsed,
               note_.empty() ? "" : " ", note_.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace mbk
