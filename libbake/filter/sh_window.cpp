// SH window factors (see sh_window.h).
#include "libbake/filter/sh_window.h"

#include <cmath>
#include <numbers>

#include "formats/error.h"

namespace mbk {

std::string window_name(ShWindow w) {
  switch (w) {
    case ShWindow::none:
      return "none";
    case ShWindow::hann:
      return "hann";
    case ShWindow::lanczos:
      return "lanczos";
  }
  return "none";
}

ShWindow parse_window(const std::string& name) {
  for (ShWindow w : {ShWindow::none, ShWindow::hann, ShWindow::lanczos})
    if (window_name(w) == name) return w;
  throw Error(ExitCode::bad_command_line, "unknown SH window '" + name + "' (expected none, hann or lanczos)",
              "--window");
}

std::vector<double> window_factors(ShWindow w, int order) {
  std::vector<double> f(size_t(order) + 1, 1.0);
  for (int l = 1; l <= order; ++l) {
    const double x = std::numbers::pi * l / (order + 1.0);
    if (w == ShWindow::hann) f[size_t(l)] = 0.5 * (1.0 + std::cos(x));
    if (w == ShWindow::lanczos) f[size_t(l)] = std::sin(x) / x;
  }
  return f;
}

}  // namespace mbk
