// Shading with filtered NDFs (see filtered_ndf_shading.h).
#include "libbake/eval/filtered_ndf_shading.h"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>
#include <numbers>
#include <string>

#include "formats/error.h"
#include "libbake/core/gauss_legendre.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

int order_of_count(size_t count) {
  const int order = int(std::lround(std::sqrt(double(count)))) - 1;
  if (order < 0 || size_t(sh_count(order)) != count)
    throw Error(ExitCode::runtime_failure, "internal: " + std::to_string(count) + " is not an SH coefficient count");
  return order;
}

// rhat_l of f over the given panels of [-1, 1] (f taken as 0 outside them), n Gauss-Legendre nodes each.
std::vector<double> zonal_coefficients_on(const std::function<double(double)>& f, int order,
                                          const std::vector<std::pair<double, double>>& panels, int n) {
  std::vector<double> rhat(size_t(order) + 1, 0.0), zonal(size_t(order) + 1);
  for (const auto& [a, b] : panels) {
    const std::vector<QuadratureNode> rule = composite_gauss_legendre(a, b, 1, n);
    for (size_t i = 0; i < rule.size(); ++i) {
      const double ft = f(rule[i].x);
      zonal_harmonics(order, rule[i].x, zonal);
      for (int l = 0; l <= order; ++l) rhat[size_t(l)] += 2 * kPi * rule[i].w * ft * zonal[size_t(l)];
    }
  }
  for (int l = 0; l <= order; ++l) rhat[size_t(l)] *= std::sqrt(4 * kPi / (2 * l + 1));  // [Han07] Eq. (7.11)
  return rhat;
}

}  // namespace

std::vector<double> zonal_brdf_coefficients(const std::function<double(double)>& f, int order) {
  return zonal_coefficients_on(f, order, {{-1.0, 0.0}, {0.0, 1.0}}, order + 32);
}

std::vector<double> lambertian_rhat(int order) {
  return zonal_brdf_coefficients([](double t) { return std::max(t, 0.0); }, order);
}

std::vector<double> microfacet_rhat(const MicrofacetLobe& lobe, int order) {
  // Panels [1 - 2^-k, 1 - 2^-(k+1)]: a lobe of width ~alpha^2 / 2 in t spans a few of them, so each panel sees
  // a smooth, unresolved-free piece; 2^-48 is below any alpha >= 0.001 (width 5e-7).
  std::vector<std::pair<double, double>> panels;
  double a = 0.0;
  for (int k = 1; k <= 48; ++k) {
    const double b = 1.0 - std::ldexp(1.0, -k);
    panels.emplace_back(a, b);
    a = b;
  }
  panels.emplace_back(a, 1.0);
  return zonal_coefficients_on([&](double t) { return microfacet_d(lobe, t); }, order, panels, order / 2 + 24);
}

double sh_filtered_brdf(const ShBasisEvaluator& basis, std::span<const double> g, std::span<const double> window,
                        std::span<const double> rhat, const Vec3& w) {
  const int order = basis.order();
  if (g.size() < size_t(basis.count()) || window.size() < size_t(order) + 1 || rhat.size() < size_t(order) + 1)
    throw Error(ExitCode::runtime_failure, "internal: SH shading inputs shorter than the order");
  std::vector<double> y(size_t(basis.count()));
  basis.evaluate(w, y);
  double sum = 0.0;
  for (int l = 0; l <= order; ++l) {
    double band = 0.0;
    for (int m = -l; m <= l; ++m) band += g[size_t(sh_index(l, m))] * y[size_t(sh_index(l, m))];
    sum += window[size_t(l)] * rhat[size_t(l)] * band;  // [Han07] Eq. (7.12)
  }
  return sum;
}

void delta_ndf_coefficients(const ShBasisEvaluator& basis, const Vec3& n, std::span<double> g) { basis.evaluate(n, g); }

std::vector<double> vmf_filtered_rhat(std::span<const double> rhat, double kappa) {
  std::vector<double> out(rhat.size());
  vmf_band_factors(kappa, out);
  for (size_t l = 0; l < out.size(); ++l) out[l] *= rhat[l];
  return out;
}

double vmf_filtered_brdf(std::span<const VmfLobeShape> lobes, std::span<const std::vector<double>> filtered,
                         const Vec3& w) {
  if (filtered.size() != lobes.size())
    throw Error(ExitCode::runtime_failure, "internal: one filtered rhat per vMF lobe is needed");
  double sum = 0.0;
  std::vector<double> zonal;
  for (size_t j = 0; j < lobes.size(); ++j) {
    const VmfLobeShape& lobe = lobes[j];
    if (lobe.alpha <= 0.0 || filtered[j].empty()) continue;
    const int order = int(filtered[j].size()) - 1;
    zonal.resize(filtered[j].size());
    zonal_harmonics(order, w.dot(lobe.mu), zonal);
    double r = 0.0;
    // rhat_l g_l Y_l0 with g_l = Lambda_l sqrt((2l+1)/(4 pi)) the lobe's zonal coefficient ([Han07] Eq. 7.14).
    for (int l = 0; l <= order; ++l)
      r += filtered[j][size_t(l)] * std::sqrt((2 * l + 1) / (4 * kPi)) * zonal[size_t(l)];
    sum += lobe.alpha * r;
  }
  return sum;
}

double vmf_filtered_brdf(std::span<const VmfLobeShape> lobes, std::span<const double> rhat, const Vec3& w) {
  std::vector<std::vector<double>> filtered;
  for (const VmfLobeShape& lobe : lobes)
    filtered.push_back(lobe.alpha > 0.0 ? vmf_filtered_rhat(rhat, lobe.kappa) : std::vector<double>());
  return vmf_filtered_brdf(lobes, filtered, w);
}

double vmf_filtered_blinn_phong_exponent(double s, double kappa) {
  if (std::isinf(kappa)) return s;
  return kappa * s / (kappa + s);  // [Han07] Eq. (7.20)
}

double blinn_phong_lobe(double s, double t) { return t <= 0.0 ? 0.0 : (s + 1) / (2 * kPi) * std::pow(t, s); }

double vmf_filtered_beckmann_alpha(double alpha, double kappa) {
  return std::sqrt(alpha * alpha + 2.0 / kappa);  // [Han07] Eq. (7.21), sigma^2 = alpha^2 / 4; 2 / inf = 0
}

double toksvig_variance(double mean_length) {
  if (!(mean_length > 0.0)) return std::numeric_limits<double>::infinity();
  return std::max(0.0, 1.0 - mean_length) / mean_length;  // lengths a hair above 1 (float rounding) are sharp
}

double toksvig_blinn_phong_exponent(double s, double mean_length) {
  return s / (1.0 + s * toksvig_variance(mean_length));
}

double toksvig_beckmann_alpha(double alpha, double mean_length) {
  return std::sqrt(alpha * alpha + 2.0 * toksvig_variance(mean_length));
}

double vmf_sh_lighting(std::span<const double> light, std::span<const double> filtered, std::span<const double> y_mu) {
  const int order = order_of_count(light.size());
  if (filtered.size() < size_t(order) + 1 || y_mu.size() < light.size())
    throw Error(ExitCode::runtime_failure, "internal: rhat or Y(mu) shorter than the lighting order");
  double sum = 0.0;
  for (int l = 0; l <= order; ++l) {
    double band = 0.0;
    for (int m = -l; m <= l; ++m) band += light[size_t(sh_index(l, m))] * y_mu[size_t(sh_index(l, m))];
    sum += filtered[size_t(l)] * band;  // [Han07] Eq. (7.23)
  }
  return sum;
}

double vmf_sh_lighting(std::span<const double> light, std::span<const double> rhat, double kappa, const Vec3& mu) {
  const int order = order_of_count(light.size());
  if (rhat.size() < size_t(order) + 1)
    throw Error(ExitCode::runtime_failure, "internal: rhat shorter than the lighting order");
  std::vector<double> y(light.size());
  ShBasisEvaluator(order).evaluate(mu, y);
  return vmf_sh_lighting(light, vmf_filtered_rhat(rhat.first(size_t(order) + 1), kappa), y);
}

}  // namespace mbk
