// The mirror image of a half-vector lobe as isotropic lobes (see reflected_lobe.h).
#include "libbake/histogram/reflected_lobe.h"

#include <algorithm>
#include <cmath>

namespace mbk {

ReflectedLobes reflected_lobes(const Vec3& w, const Vec3& v, double sigma) {
  ReflectedLobes out;
  const double c = std::clamp(w.dot(v), 0.0, 1.0);
  const Vec3 mirror = (2.0 * c * w - v).normalized();
  const Vec3 across = v - c * w;  // v's part perpendicular to w: its length is sin(theta_d)
  const double sine = across.norm();
  const double major = 2.0 * sigma, minor_exact = 2.0 * sigma * c;
  const double ratio = minor_exact > 0.0 ? sine / c : INFINITY;  // spread / minor width, uncapped
  if (!(ratio > kIsotropicRatio) || !(sine > 1e-12)) {
    // Nearly isotropic: one lobe of the mean variance.
    out.count = 1;
    out.table_sigma = std::sqrt(0.5 * (major * major + minor_exact * minor_exact)) / 2.0;
    out.axes[0] = mirror;
    out.weights[0] = 1.0;
    out.view_cosines[0] = c;
    return out;
  }
  // Axes at steps of at most 1.5 minor widths over +-3 spreads: K = 2 ceil(2 spread / minor) + 1.
  int k = 2 * int(std::ceil(std::min(2.0 * ratio, 1e6))) + 1;
  double minor = minor_exact;
  if (k > kMaxReflectedLobes) {
    k = kMaxReflectedLobes;
    const double q = (k - 1) / 4.0;
    minor = major / std::sqrt(1.0 + q * q);
  }
  out.count = k;
  out.table_sigma = minor / 2.0;
  const double spread = std::min(std::sqrt(std::max(0.0, major * major - minor * minor)), kMaxSpread);
  // The in-plane direction at the mirror direction: the image of a unit offset along e = across / sine.
  const Vec3 e = across / sine;
  const Vec3 along = (e.dot(v) * w + c * e).normalized();
  double total = 0.0;
  for (int i = 0; i < k; ++i) {
    // Three axes: the 3-point Gauss-Hermite rule (exact variance); more: equal steps over +-3 spreads.
    const double x = k == 3 ? std::sqrt(3.0) * (i - 1) : -3.0 + 6.0 * i / (k - 1);
    const double angle = spread * x;
    out.axes[size_t(i)] = std::cos(angle) * mirror + std::sin(angle) * along;
    out.weights[size_t(i)] = k == 3 ? (i == 1 ? 2.0 / 3.0 : 1.0 / 6.0) : std::exp(-0.5 * x * x);
    out.view_cosines[size_t(i)] = c * std::cos(angle / 2.0) + sine * std::sin(angle / 2.0);
    total += out.weights[size_t(i)];
  }
  for (int i = 0; i < k; ++i) out.weights[size_t(i)] /= total;
  return out;
}

}  // namespace mbk
