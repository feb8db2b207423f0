// The reflected lobes' band factors by roughness (see roughness_zh_table.h).
#include "libbake/histogram/roughness_zh_table.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"
#include "libbake/core/sh_basis.h"
#include "libbake/core/vmf_lobe.h"

namespace mbk {

RoughnessZhTable::RoughnessZhTable(int order) : order_(order) {
  if (order < 0 || order > kMaxShOrder)
    throw Error(ExitCode::runtime_failure, "roughness ZH table: order out of range");
  const size_t n = size_t(order) + 1;
  lambda_.resize((kSteps + 1) * n);
  for (int k = 0; k <= kSteps; ++k) {
    const double s = double(k) / kSteps;
    vmf_band_factors(k == 0 ? INFINITY : 1.0 / (4.0 * s * s), std::span<double>(lambda_).subspan(size_t(k) * n, n));
  }
}

std::span<const double> RoughnessZhTable::row(int k) const {
  const size_t n = size_t(order_) + 1;
  return std::span<const double>(lambda_).subspan(size_t(std::clamp(k, 0, kSteps)) * n, n);
}

void RoughnessZhTable::band_factors(double s, std::span<double> out) const {
  const double x = std::clamp(std::isnan(s) ? 1.0 : s, 0.0, 1.0) * kSteps;
  const int k = std::min(int(x), kSteps - 1);
  const double t = x - k;
  const std::span<const double> a = row(k), b = row(k + 1);
  for (int l = 0; l <= order_; ++l) out[size_t(l)] = (1.0 - t) * a[size_t(l)] + t * b[size_t(l)];
}

double narrowest_resolved_roughness(int order) {
  return order <= 0 ? 1.0 : std::sqrt(1.0 / (double(order) * (order + 1.0)));
}

}  // namespace mbk
