// The roughness lobe and its sampler (see roughness_lobe.h).
#include "libbake/histogram/roughness_lobe.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "libbake/core/vmf_lobe.h"

namespace mbk {

double lobe_kappa(double sigma) {
  const double s = std::clamp(std::isnan(sigma) ? 1.0 : sigma, kMinLobeRoughness, 1.0);
  return 1.0 / (s * s);
}

double roughness_lobe(double cos_angle, double sigma) {
  return std::exp(vmf_log_density(lobe_kappa(sigma), std::clamp(cos_angle, -1.0, 1.0)));
}

Vec3 sample_roughness_lobe(const Vec3& mu, double sigma, double u1, double u2) {
  const double kappa = lobe_kappa(sigma);
  const double c = vmf_cos_from_uniform(kappa, u1);
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  const double phi = 2.0 * std::numbers::pi * u2;
  // An orthonormal frame around mu (Duff et al. 2017).
  const double sign = std::copysign(1.0, mu.z());
  const double a = -1.0 / (sign + mu.z()), b = mu.x() * mu.y() * a;
  const Vec3 t(1.0 + sign * mu.x() * mu.x() * a, sign * b, -sign * mu.x());
  const Vec3 bt(b, sign + mu.y() * mu.y() * a, -mu.y());
  return (c * mu + s * std::cos(phi) * t + s * std::sin(phi) * bt).normalized();
}

}  // namespace mbk
