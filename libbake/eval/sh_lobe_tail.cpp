// The SH bands beyond the stored order, completed from the footprint's vMF lobe (see sh_lobe_tail.h).
#include "libbake/eval/sh_lobe_tail.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "libbake/core/sh_basis.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/eval/filtered_ndf_shading.h"

namespace mbk {
namespace {

constexpr int kAngles = 1024, kKappas = 96;
constexpr double kLogKappaMin = -4.605170185988091, kLogKappaMax = 18.420680743952367;  // log 1e-2, log 1e8
constexpr double kPi = std::numbers::pi;

double angle_step() { return kPi / (kAngles - 1); }
double log_kappa_step() { return (kLogKappaMax - kLogKappaMin) / (kKappas - 1); }

}  // namespace

ShLobeTail::ShLobeTail(const MicrofacetLobe& lobe, int order) {
  const int top = std::clamp(int(std::ceil(8.0 / std::max(lobe.alpha, 1e-3))), 4 * order + 4, 2048);
  const std::vector<double> rhat = microfacet_rhat(lobe, top);
  table_.assign(size_t(kKappas + 1) * kAngles, 0.0);
  std::vector<double> lambda(size_t(top) + 1), zonal(size_t(top) + 1);
  // tail = sum_{l > L} c_l P_l, with P_l = sqrt(4 pi / (2l + 1)) Y_l0 (zonal_harmonics gives Y_l0).
  std::vector<std::vector<double>> coefficient(kKappas + 1, std::vector<double>(size_t(top) + 1, 0.0));
  for (int k = 0; k <= kKappas; ++k) {
    if (k < kKappas)
      vmf_band_factors(std::exp(kLogKappaMin + k * log_kappa_step()), lambda);
    else
      std::fill(lambda.begin(), lambda.end(), 1.0);
    for (int l = order + 1; l <= top; ++l)
      coefficient[size_t(k)][size_t(l)] =
          rhat[size_t(l)] * lambda[size_t(l)] * std::sqrt((2 * l + 1) / (4 * kPi));  // times Y_l0 = P_l sqrt(..)
  }
  for (int a = 0; a < kAngles; ++a) {
    zonal_harmonics(top, std::cos(a * angle_step()), zonal);
    for (int k = 0; k <= kKappas; ++k) {
      double sum = 0.0;
      for (int l = order + 1; l <= top; ++l) sum += coefficient[size_t(k)][size_t(l)] * zonal[size_t(l)];
      table_[size_t(k) * kAngles + size_t(a)] = sum;
    }
  }
}

double ShLobeTail::value(double cos_angle, double kappa) const {
  const double x = std::acos(std::clamp(cos_angle, -1.0, 1.0)) / angle_step();
  const size_t a = std::min(size_t(x), size_t(kAngles - 2));
  const double fa = std::min(1.0, x - double(a));
  const auto row = [&](size_t k) {
    const double* r = &table_[k * kAngles];
    return (1.0 - fa) * r[a] + fa * r[a + 1];
  };
  if (std::isinf(kappa)) return row(kKappas);
  const double y = (std::log(std::max(kappa, 1e-300)) - kLogKappaMin) / log_kappa_step();
  if (!(y > 0.0)) return row(0);  // kappa <= 1e-2 (or NaN): Lambda_l <= 1e-2^l / (2l+1)!!, nothing beyond L
  if (y >= kKappas - 1) return row(kKappas - 1);  // kappa >= 1e8: Lambda_l = exp(-l(l+1)/(2 kappa)) > 0.97 to 2048
  const size_t k = size_t(y);
  const double fk = y - double(k);
  return (1.0 - fk) * row(k) + fk * row(k + 1);
}

}  // namespace mbk
