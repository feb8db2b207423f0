// Order-2 SH lighting: projection of lat-long maps, irradiance and the vMF specular approximation
// (see sh_lighting.h).
#include "libbake/eval/sh_lighting.h"

#include <cmath>
#include <numbers>

#include "formats/error.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

int band_of(int k) { return k == 0 ? 0 : k < 4 ? 1 : 2; }

Vec3 clamp_positive(const Vec3& v) { return v.cwiseMax(0.0); }

Vec3 band_weighted_sum(const ShCoefficients& sh, const Vec3& d, const std::array<double, 3>& band_weight) {
  const ShBasis y = sh_basis(d);
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < kShCount; ++k) sum += band_weight[band_of(k)] * y[k] * sh[k];
  return sum;
}

}  // namespace

ShBasis sh_basis(const Vec3& d) {
  const double c0 = 0.5 / std::sqrt(kPi), c1 = std::sqrt(3.0 / (4.0 * kPi)), c2 = std::sqrt(15.0 / (4.0 * kPi)),
               c3 = std::sqrt(5.0 / (16.0 * kPi)), c4 = std::sqrt(15.0 / (16.0 * kPi));
  const double x = d.x(), y = d.y(), z = d.z();
  return {
      c0, c1 * y, c1 * z, c1 * x, c2 * x * y, c2 * y * z, c3 * (3.0 * z * z - 1.0), c2 * x * z, c4 * (x * x - y * y)};
}

Vec3 lat_long_direction(double phi, double theta) {
  return Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
}

ShCoefficients project_lat_long(const Image& map) {
  if (map.width == 0 || map.height == 0 || map.channels == 0)
    throw Error(ExitCode::invalid_input, "empty environment map");
  ShCoefficients sh;
  sh.fill(Vec3::Zero());
  const double dphi = 2.0 * kPi / map.width;
  for (uint32_t row = 0; row < map.height; ++row) {
    const double theta_top = kPi * row / map.height, theta_bottom = kPi * (row + 1) / map.height;
    const double solid_angle = dphi * (std::cos(theta_top) - std::cos(theta_bottom));
    const double theta = kPi * (row + 0.5) / map.height;
    for (uint32_t i = 0; i < map.width; ++i) {
      Vec3 radiance;
      for (int c = 0; c < 3; ++c) radiance[c] = map.at(i, row, map.channels >= 3 ? uint32_t(c) : 0);
      if (!radiance.allFinite())
        throw Error(ExitCode::invalid_input, "non-finite radiance in environment map",
                    "texel (" + std::to_string(i) + ", " + std::to_string(row) + ")");
      const ShBasis y = sh_basis(lat_long_direction(dphi * (i + 0.5), theta));
      for (int k = 0; k < kShCount; ++k) sh[k] += (y[k] * solid_angle) * radiance;
    }
  }
  return sh;
}

ShCoefficients constant_radiance_sh(const Vec3& radiance) {
  ShCoefficients sh;
  sh.fill(Vec3::Zero());
  sh[0] = 2.0 * std::sqrt(kPi) * radiance;  // integral of L Y00 over the sphere = L 4 pi / (2 sqrt(pi))
  return sh;
}

Vec3 sh_radiance(const ShCoefficients& sh, const Vec3& d) {
  return clamp_positive(band_weighted_sum(sh, d, {1.0, 1.0, 1.0}));
}

Vec3 sh_irradiance(const ShCoefficients& sh, const Vec3& n) {
  return clamp_positive(band_weighted_sum(sh, n, {kPi, 2.0 * kPi / 3.0, kPi / 4.0}));  // [Ramamoorthi01, Eq. 8]
}

std::array<double, 3> vmf_band_factors(double kappa) {
  double l1, l2;
  if (kappa < 0.1) {
    // Series of coth(k) - 1/k and of 1 - 3 (coth(k) - 1/k) / k: the closed forms cancel catastrophically
    // as kappa -> 0 (both tend to 0 as differences of terms near 1/kappa). Absolute truncation error < 1e-12.
    const double k2 = kappa * kappa;
    l1 = kappa * (1.0 / 3.0 - k2 / 45.0 + 2.0 * k2 * k2 / 945.0 - k2 * k2 * k2 / 4725.0);
    l2 = k2 * (1.0 / 15.0 - 2.0 * k2 / 315.0 + k2 * k2 / 1575.0);
  } else {
    l1 = 1.0 / std::tanh(kappa) - 1.0 / kappa;  // coth via tanh: no overflow of sinh/cosh at large kappa
    l2 = 1.0 - 3.0 * l1 / kappa;
  }
  return {1.0, l1, l2};
}

double specular_lobe_kappa(double alpha) { return 1.0 / (2.0 * alpha * alpha); }

Vec3 sh_lobe_radiance(const ShCoefficients& sh, const Vec3& d, double kappa) {
  return clamp_positive(band_weighted_sum(sh, d, vmf_band_factors(kappa)));
}

}  // namespace mbk
