// Drawing unit vectors from a von Mises-Fisher distribution on S^2, for the vMF fit tests: Wood (1994) for the
// cosine to the mean, w = 1 + log(u + (1 - u) e^-2k) / k (stable for any kappa), and a uniform azimuth.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "libbake/core/eigen.h"

namespace mbk::test {

inline Vec3 sample_vmf(std::mt19937_64& rng, const Vec3& mu, double kappa) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double u = u01(rng), phi = 2 * std::numbers::pi * u01(rng);
  const double w = 1.0 + std::log(u + (1.0 - u) * std::exp(-2.0 * kappa)) / kappa;
  const double s = std::sqrt(std::max(0.0, 1.0 - w * w));
  const Vec3 a = std::abs(mu.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 t = mu.cross(a).normalized(), b = mu.cross(t);
  return (w * mu + s * std::cos(phi) * t + s * std::sin(phi) * b).normalized();
}

}  // namespace mbk::test
