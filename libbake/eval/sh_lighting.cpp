// Order-2 SH lighting: projection of lat-long maps, irradiance and the vMF specular approximation
// (see sh_lighting.h).
#include "libbake/eval/sh_lighting.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "formats/error.h"
#include "libbake/core/sh_basis.h"
#include "libbake/core/vmf_lobe.h"

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
  static const ShBasisEvaluator kOrder2(2);  // the shared basis (libbake/core/sh_basis.h), order 2
  ShBasis y;
  kOrder2.evaluate(d, y);
  return y;
}

Vec3 lat_long_direction(double phi, double theta) {
  return Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
}

std::vector<Vec3> project_lat_long(const Image& map, int order) {
  if (map.width == 0 || map.height == 0 || map.channels == 0)
    throw Error(ExitCode::invalid_input, "empty environment map");
  const ShBasisEvaluator basis(order);
  std::vector<Vec3> sh(size_t(basis.count()), Vec3::Zero());
  std::vector<double> y(sh.size());
  // Each texel is cut into n x n cells, each weighted by its exact solid angle: the basis is sampled at least four
  // times per quarter period of band L (cells of at most pi / (4 L)), so that high orders project the piecewise-
  // constant map instead of aliasing it; order 2 keeps one sample per texel (n = 1 for maps of >= 8 rows).
  const uint32_t n = order <= 2 ? 1 : std::clamp(uint32_t(std::ceil(4.0 * order / map.height)), 1u, 16u);
  const double dphi = 2.0 * kPi / (double(map.width) * n);
  for (uint32_t row = 0; row < map.height; ++row) {
    for (uint32_t i = 0; i < map.width; ++i) {
      Vec3 radiance;
      for (int c = 0; c < 3; ++c) radiance[c] = map.at(i, row, map.channels >= 3 ? uint32_t(c) : 0);
      if (!radiance.allFinite())
        throw Error(ExitCode::invalid_input, "non-finite radiance in environment map",
                    "texel (" + std::to_string(i) + ", " + std::to_string(row) + ")");
      for (uint32_t sr = 0; sr < n; ++sr) {
        const double sub = double(row) * n + sr, rows = double(map.height) * n;
        const double theta_top = kPi * sub / rows, theta_bottom = kPi * (sub + 1) / rows;
        const double solid_angle = dphi * (std::cos(theta_top) - std::cos(theta_bottom));
        const double theta = kPi * (sub + 0.5) / rows;
        for (uint32_t sc = 0; sc < n; ++sc) {
          basis.evaluate(lat_long_direction(dphi * (double(i) * n + sc + 0.5), theta), y);
          for (size_t k = 0; k < sh.size(); ++k) sh[k] += (y[k] * solid_angle) * radiance;
        }
      }
    }
  }
  return sh;
}

Vec2 lat_long_angles(const Vec3& d) {
  double phi = std::atan2(d.z(), d.x());
  if (phi < 0.0) phi += 2.0 * kPi;
  if (phi >= 2.0 * kPi) phi = 0.0;  // -0 rounds up to 2 pi
  return Vec2(phi, std::acos(std::clamp(d.y(), -1.0, 1.0)));
}

ShCoefficients project_lat_long(const Image& map) {
  const std::vector<Vec3> sh = project_lat_long(map, 2);
  ShCoefficients out;
  std::copy(sh.begin(), sh.end(), out.begin());
  return out;
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
  std::array<double, 3> lambda;
  mbk::vmf_band_factors(kappa, lambda);  // the exact Bessel ratios (libbake/core/vmf_lobe.h)
  return lambda;
}

double specular_lobe_kappa(double alpha) { return 1.0 / (2.0 * alpha * alpha); }

Vec3 sh_lobe_radiance(const ShCoefficients& sh, const Vec3& d, double kappa) {
  return clamp_positive(band_weighted_sum(sh, d, vmf_band_factors(kappa)));
}

}  // namespace mbk
