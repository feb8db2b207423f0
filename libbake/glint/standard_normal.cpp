// The standard normal distribution (see standard_normal.h).
#include "libbake/glint/standard_normal.h"

#include <cmath>
#include <limits>

namespace mbk {
namespace {

constexpr double kSqrt2Pi = 2.50662827463100050242;   // sqrt(2 pi)
constexpr double kInvSqrt2 = 0.70710678118654752440;  // 1 / sqrt(2)

// Peter J. Acklam's rational approximation of Phi^-1 on (0, 1/2] ("An algorithm for computing the inverse normal
// cumulative distribution function", 2003): relative error below 1.15e-9, a starting point for Halley's method.
double acklam_lower(double p) {
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                                 1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                                 6.680131188771972e+01, -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                                 -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                 3.754408661907416e+00};
  constexpr double kLowRegion = 0.02425;
  if (p < kLowRegion) {
    const double q = std::sqrt(-2.0 * std::log(p));
    return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  const double q = p - 0.5, r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
}

// Phi^-1(p) for p in (0, 1/2]. Halley's method on f(x) = Phi(x) - p, with f' = phi(x) and f'' = -x phi(x):
//
//     u = (Phi(x) - p) / phi(x),        x <- x - u / (1 + x u / 2).
//
// In the far tail Phi(x) - p and phi(x) are both near the bottom of the double range (p = 1e-300: the difference
// would be subnormal, and exp(x^2 / 2) alone overflows below x ~ -37.7), so u is computed as
//
//     u = (Phi(x) / p - 1) * sqrt(2 pi) * exp(log(p) + x^2 / 2),
//
// a relative residual times the Mills-ratio-like factor p / phi(x), both well scaled. Each Halley step triples
// the number of correct digits: one or two steps take Acklam's 1e-9 to full precision; the loop stops when the
// step is below an ulp of x (p = 1/2: x = 0 exactly, the residual is 0).
double lower_quantile(double p) {
  double x = acklam_lower(p);
  for (int iteration = 0; iteration < 4; ++iteration) {
    const double residual = standard_normal_cdf(x) / p - 1.0;
    const double u = residual * kSqrt2Pi * std::exp(std::log(p) + 0.5 * x * x);
    const double step = u / (1.0 + 0.5 * x * u);
    x -= step;
    if (!(std::abs(step) > std::numeric_limits<double>::epsilon() * std::abs(x))) break;
  }
  return x;
}

}  // namespace

double standard_normal_pdf(double x) { return std::exp(-0.5 * x * x) / kSqrt2Pi; }

double standard_normal_cdf(double x) { return 0.5 * std::erfc(-x * kInvSqrt2); }

double standard_normal_quantile(double p) {
  if (std::isnan(p)) return p;
  if (p <= 0.0) return -std::numeric_limits<double>::infinity();
  if (p >= 1.0) return std::numeric_limits<double>::infinity();
  // 1 - p is exact for p in [1/2, 1] (Sterbenz), so the upper tail is the mirror of the lower one.
  return p <= 0.5 ? lower_quantile(p) : -lower_quantile(1.0 - p);
}

}  // namespace mbk
