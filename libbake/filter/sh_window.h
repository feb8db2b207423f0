// Windows for truncated SH expansions of NDFs ([Han07] Sec. 7.4; Sloan, "Stupid Spherical Harmonics Tricks",
// GDC 2008, for windowing SH): a truncated expansion of a peaked NDF rings (it goes negative around the
// peak); multiplying band l by a factor w_l that falls smoothly to 0 past the order trades sharpness for
// less ringing. The factors are applied at evaluation (g_lm w_l), never baked into the stored coefficients,
// which stay exact means of Y_lm (so `validate` can check them).
#pragma once

#include <string>
#include <vector>

namespace mbk {

enum class ShWindow { none, hann, lanczos };

std::string window_name(ShWindow w);             // "none", "hann", "lanczos"
ShWindow parse_window(const std::string& name);  // Error(bad_command_line) for other names

// w_l for l = 0..order, all in (0, 1] and non-increasing, w_0 = 1:
//   none     1
//   hann     (1 + cos(pi l / (order + 1))) / 2
//   lanczos  sinc(l / (order + 1)) = sin(pi l / (order + 1)) / (pi l / (order + 1))
std::vector<double> window_factors(ShWindow w, int order);

}  // namespace mbk
