// The moment-matched view-dependent slope distribution (see slope_filtering.h for the derivation).
#include "libbake/colormap/slope_filtering.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"

namespace mbk {
namespace {

// Below this k the closed forms of T_n lose more than ~4 digits to cancellation; the asymptotic series is then
// accurate to about e^(-k^2 / 2) relative (its smallest term).
constexpr double kSeriesBelow = -10.0;

// The moments of x ~ N(k, 1) weighted by x_+: E_w[x] = T_2 / T_1 and Var_w[x] = T_3 / T_1 - E_w[x]^2, and
// T_1 / phi(k).
struct WeightedMoments {
  double mean, variance, t1_over_pdf;
};

// c^(n+1) I_n(c) / n! by the asymptotic series (1 + sum_j>0 (-1/2)^j (n+2j)! / (n! j! c^(2j))), summed while the
// terms decrease; scaled so that nothing overflows or underflows for any c >= 10.
double scaled_series(int n, double c) {
  double term = 1.0, sum = 1.0;
  for (int j = 0; j < 400; ++j) {
    const double next = term * (-0.5) / (j + 1) * (n + 2.0 * j + 1) * (n + 2.0 * j + 2) / (c * c);
    if (std::abs(next) >= std::abs(term) || std::abs(next) < 1e-18) break;
    term = next;
    sum += term;
  }
  return sum;
}

WeightedMoments weighted_moments(double k) {
  if (k < kSeriesBelow) {
    // I_1 = J_1 / c^2, I_2 = 2 J_2 / c^3, I_3 = 6 J_3 / c^4 with J_n = scaled_series(n, c).
    const double c = -k, j1 = scaled_series(1, c), j2 = scaled_series(2, c), j3 = scaled_series(3, c);
    const double mean = 2.0 * j2 / (c * j1), second = 6.0 * j3 / (c * c * j1);
    return {mean, std::max(0.0, second - mean * mean), j1 / (c * c)};
  }
  const double ratio = 0.5 * std::erfc(-k / std::sqrt(2.0)) / (std::exp(-0.5 * k * k) / std::sqrt(2.0 * M_PI));
  const double t1 = k * ratio + 1.0, t2 = (k * k + 1.0) * ratio + k, t3 = (k * k * k + 3.0 * k) * ratio + (k * k + 2.0);
  const double mean = t2 / t1;
  return {mean, std::max(0.0, t3 / t1 - mean * mean), t1};
}

}  // namespace

VisibleSlopes visible_slope_distribution(const SlopeGaussian& slopes, const Vec3& wo) {
  if (!(wo.z() > 0.0)) throw Error(ExitCode::runtime_failure, "internal: view direction below the mean surface");
  const double a = wo.z();
  const Vec2 b(-wo.x(), -wo.y());
  const Vec2 sigma_b = slopes.covariance * b;
  const double m = b.dot(slopes.mean), v = b.dot(sigma_b);
  VisibleSlopes out;
  out.gaussian = slopes;
  if (!(v > 0.0)) {  // head-on, or no slope variance along b: the weight a + m is constant
    out.projected_area = std::max(a + m, 0.0);
    return out;
  }
  const double sd = std::sqrt(v), k = (a + m) / sd;
  const WeightedMoments x = weighted_moments(k);
  const double mean_t = sd * x.mean - a, var_t = v * x.variance;
  out.gaussian.mean = slopes.mean + sigma_b * ((mean_t - m) / v);
  out.gaussian.covariance = slopes.covariance + sigma_b * sigma_b.transpose() * ((var_t - v) / (v * v));
  out.projected_area = sd * x.t1_over_pdf * std::exp(-0.5 * k * k) / std::sqrt(2.0 * M_PI);  // sqrt(v) T_1
  return out;
}

DriverStatistics slope_driver(const SlopeGaussian& slopes, const Vec2& direction) {
  return {direction.dot(slopes.mean), std::sqrt(std::max(0.0, direction.dot(slopes.covariance * direction)))};
}

}  // namespace mbk
