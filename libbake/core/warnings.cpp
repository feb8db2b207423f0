// The process's warning handler (see warnings.h).
#include "libbake/core/warnings.h"

#include <mutex>
#include <utility>

namespace mbk {
namespace {

std::mutex& handler_mutex() {
  static std::mutex m;
  return m;
}

WarningHandler& installed_handler() {
  static WarningHandler h;
  return h;
}

}  // namespace

WarningHandler set_warning_handler(WarningHandler handler) {
  std::lock_guard lock(handler_mutex());
  return std::exchange(installed_handler(), std::move(handler));
}

void warn(const std::string& what, const std::string& where) {
  std::lock_guard lock(handler_mutex());
  if (installed_handler()) installed_handler()(what, where);
}

}  // namespace mbk
