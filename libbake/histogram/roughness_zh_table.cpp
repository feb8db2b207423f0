// The roughness lobe, its sampling and its zonal-harmonic table (see roughness_zh_table.h).
#include "libbake/histogram/roughness_zh_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "formats/error.h"
#include "libbake/core/gauss_legendre.h"
#include "libbake/core/vmf_lobe.h"

namespace mbk {
namespace {

constexpr double kQuadratureRange = 60.0;  // e^{-60} ~ 1e-26: nothing of the lobe's mass lies beyond
constexpr int kNodesPerPanel = 16;

}  // namespace

double lobe_kappa(double sigma) {
  const double s = std::clamp(std::isnan(sigma) ? 1.0 : sigma, kMinLobeRoughness, 1.0);
  return 1.0 / (s * s);
}

double roughness_lobe(double cos_angle, double sigma) {
  return std::exp(vmf_log_density(lobe_kappa(sigma), std::clamp(cos_angle, -1.0, 1.0)));
}

Vec3 sample_roughness_lobe(const Vec3& mu, double sigma, double u1, double u2) {
  const double kappa = lobe_kappa(sigma);
  // cos from the inverse of its distribution function, without cancellation near the axis (log1p, expm1).
  const double c = std::clamp(1.0 + std::log1p(u1 * std::expm1(-2.0 * kappa)) / kappa, -1.0, 1.0);
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  const double phi = 2.0 * std::numbers::pi * u2;
  // An orthonormal frame around mu (Duff et al. 2017).
  const double sign = std::copysign(1.0, mu.z());
  const double a = -1.0 / (sign + mu.z()), b = mu.x() * mu.y() * a;
  const Vec3 t(1.0 + sign * mu.x() * mu.x() * a, sign * b, -sign * mu.x());
  const Vec3 bt(b, sign + mu.y() * mu.y() * a, -mu.y());
  return (c * mu + s * std::cos(phi) * t + s * std::sin(phi) * bt).normalized();
}

double narrowest_resolved_roughness(int order) {
  return order <= 0 ? 1.0 : std::sqrt(1.0 / (double(order) * (order + 1.0)));
}

void zonal_lobe_band_factors(double kappa, std::span<double> out) {
  if (out.empty()) return;
  if (std::isinf(kappa)) {
    std::fill(out.begin(), out.end(), 1.0);
    return;
  }
  if (!(kappa > 0.0)) throw Error(ExitCode::runtime_failure, "zonal lobe: kappa must be positive");
  const int order = int(out.size()) - 1;
  const double range = std::min(2.0 * kappa, kQuadratureRange);
  // Panels: one per unit of u for e^{-u}, and ~one per half period of P_L over the t-range the panel spans.
  const int panels = int(std::ceil(range)) + int(std::ceil(order * range / kappa));
  std::vector<double> sum(out.size(), 0.0);
  double mass = 0.0;
  for (const QuadratureNode& q : composite_gauss_legendre(0.0, range, panels, kNodesPerPanel)) {
    const double w = q.w * std::exp(-q.x);
    const double t = 1.0 - q.x / kappa;
    mass += w;
    double p_prev = 1.0, p = t;  // P_0, P_1
    sum[0] += w;
    if (order >= 1) sum[1] += w * t;
    for (int l = 1; l < order; ++l) {
      const double next = ((2.0 * l + 1.0) * t * p - l * p_prev) / (l + 1.0);
      p_prev = p;
      p = next;
      sum[size_t(l) + 1] += w * p;
    }
  }
  for (size_t l = 0; l < out.size(); ++l) out[l] = sum[l] / mass;
}

RoughnessZhTable::RoughnessZhTable(int order) : order_(order) {
  if (order < 0 || order > kMaxShOrder)
    throw Error(ExitCode::runtime_failure, "roughness ZH table: order out of range");
  const size_t n = size_t(order) + 1;
  lambda_.resize((kSteps + 1) * n);
  for (int k = 0; k <= kSteps; ++k) {
    const double sigma = double(k) / kSteps;
    const double kappa_reflected = k == 0 ? INFINITY : 1.0 / (4.0 * sigma * sigma);
    zonal_lobe_band_factors(kappa_reflected, std::span<double>(lambda_).subspan(size_t(k) * n, n));
  }
}

std::span<const double> RoughnessZhTable::row(int k) const {
  const size_t n = size_t(order_) + 1;
  return std::span<const double>(lambda_).subspan(size_t(std::clamp(k, 0, kSteps)) * n, n);
}

void RoughnessZhTable::band_factors(double sigma, std::span<double> out) const {
  const double x = std::clamp(std::isnan(sigma) ? 1.0 : sigma, 0.0, 1.0) * kSteps;
  const int k = std::min(int(x), kSteps - 1);
  const double t = x - k;
  const std::span<const double> a = row(k), b = row(k + 1);
  for (int l = 0; l <= order_; ++l) out[size_t(l)] = (1.0 - t) * a[size_t(l)] + t * b[size_t(l)];
}

void add_rotated_zonal_lobe(const ShBasisEvaluator& basis, const Vec3& w, std::span<const double> lambda, double weight,
                            std::span<double> out, std::span<double> scratch) {
  basis.evaluate(w, scratch);
  for (int l = 0; l <= basis.order(); ++l) {
    const double f = weight * lambda[size_t(l)];
    for (int m = -l; m <= l; ++m) out[size_t(sh_index(l, m))] += f * scratch[size_t(sh_index(l, m))];
  }
}

}  // namespace mbk
