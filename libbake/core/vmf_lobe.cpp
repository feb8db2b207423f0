// vMF lobe functions (see vmf_lobe.h): mean length, its inverse, log density, Bessel-ratio band factors.
#include "libbake/core/vmf_lobe.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "formats/error.h"

namespace mbk {
namespace {

constexpr double kSeriesLimit = 0.1;  // below: the derivative's polynomial series
constexpr double kDirectLimit = 2.0;  // below: A from the cancellation-free series; above: 1 - (1 - A)
// Above: e^-2k (< 2e-35) is below an ulp of every term it is added to, so the formulas drop it, with the same bits,
// and exp is not called into its slow underflow path (kappa_max is 1e6).
constexpr double kNoExpLimit = 40.0;

// A(k) = (k cosh k - sinh k) / (k sinh k), whose numerator sum_{n>=1} 2n k^(2n+1) / (2n+1)! has only positive
// terms (the textbook coth(k) - 1/k loses ~log10(3 / k^2) digits to cancellation below k ~ 2). Below k = 1e-8,
// A = k/3 to 1e-17 relative (and k^3 would underflow for tiny k).
double mean_length_series(double k) {
  if (k < 1e-8) return k / 3.0;
  const double k2 = k * k;
  double term = k * k2 / 6.0, numerator = 0.0;  // term = k^(2n+1) / (2n+1)!, n = 1
  for (int n = 1; n < 60; ++n) {
    numerator += 2.0 * n * term;
    term *= k2 / ((2.0 * n + 2.0) * (2.0 * n + 3.0));
    if (2.0 * (n + 1) * term < 1e-18 * numerator) break;
  }
  return numerator / (k * std::sinh(k));
}

// dA/dk: the series' derivative below 0.1; above, 1/k^2 - 1/sinh^2(k) with 1/sinh^2 = 4 e^-2k / (1 - e^-2k)^2.
double mean_length_derivative(double k) {
  if (k < kSeriesLimit) {
    const double k2 = k * k;
    return 1.0 / 3.0 + k2 * (-3.0 / 45.0 + k2 * (10.0 / 945.0 + k2 * (-7.0 / 4725.0 + k2 * (18.0 / 93555.0))));
  }
  if (k > kNoExpLimit) return 1.0 / (k * k);
  const double e = std::exp(-2.0 * k), d = -std::expm1(-2.0 * k);
  return 1.0 / (k * k) - 4.0 * e / (d * d);
}

// r / |r| for a mean resultant r of length |r| (+z for r = 0).
Vec3 unit_resultant(const Vec3& r, double length) { return length > 0.0 ? Vec3(r / length) : Vec3::UnitZ(); }

}  // namespace

double vmf_mean_length(double kappa) {
  if (kappa <= 0.0) return 0.0;
  if (kappa < kDirectLimit) return mean_length_series(kappa);
  return 1.0 - vmf_one_minus_mean_length(kappa);
}

double vmf_one_minus_mean_length(double kappa) {
  if (kappa < kDirectLimit) return 1.0 - vmf_mean_length(kappa);
  if (std::isinf(kappa)) return 0.0;
  if (kappa > kNoExpLimit) return 1.0 / kappa;
  // coth(k) = 1 + 2 e^-2k / (1 - e^-2k), so 1 - A = 1/k - 2 e^-2k / (1 - e^-2k): no overflow, and above k = 2
  // the second term is below 8% of the first (no significant cancellation).
  return 1.0 / kappa - 2.0 * std::exp(-2.0 * kappa) / -std::expm1(-2.0 * kappa);
}

double vmf_kappa_closed_form(double r) { return (3.0 * r - r * r * r) / (1.0 - r * r); }

double vmf_kappa_from_mean_length(double r, double kappa_max) {
  if (std::isnan(r)) throw Error(ExitCode::runtime_failure, "internal: vMF mean length is NaN");
  if (r <= 0.0) return 0.0;
  // The cap: r at or past A(kappa_max) (r >= 1 for identical normals, r slightly above 1 from rounding).
  if (r >= 1.0 || vmf_one_minus_mean_length(kappa_max) >= 1.0 - r) return kappa_max;
  // Solve in 1 - A where r > 1/2: 1 - r is exact there (Sterbenz), so kappa ~ 1 / (1 - r) keeps its precision.
  const bool upper = r > 0.5;
  const double target = upper ? 1.0 - r : r;
  auto residual = [&](double k) { return upper ? target - vmf_one_minus_mean_length(k) : vmf_mean_length(k) - target; };
  double lo = 3.0 * r, hi = 1.0 / (1.0 - r);  // residual(lo) <= 0 <= residual(hi): A is increasing
  double k = std::clamp(vmf_kappa_closed_form(r), lo, hi);
  for (int it = 0; it < 200; ++it) {
    const double f = residual(k);
    if (f == 0.0) break;
    (f < 0.0 ? lo : hi) = k;
    const double step = f / mean_length_derivative(k);  // d residual / dk = A'(k) in both forms
    double next = k - step;
    // Guard: a step leaving the bracket (or a derivative that underflowed) bisects instead, geometrically
    // when the bracket spans decades.
    if (!(next > lo && next < hi)) next = hi > 4.0 * lo ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
    if (std::abs(next - k) <= 4.0 * std::numeric_limits<double>::epsilon() * k) {
      k = next;
      break;
    }
    k = next;
    if (hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * lo) break;
  }
  return std::min(k, kappa_max);
}

double vmf_log_density(double kappa, double cos_angle) {
  constexpr double kLog4Pi = 2.5310242469692907930;  // log(4 pi)
  // kappa / (1 - e^-2k) -> 1/2 as k -> 0, and expm1 keeps it exact for any positive kappa (even subnormal).
  if (kappa <= 0.0) return -kLog4Pi;
  const double one_minus = kappa > kNoExpLimit ? 1.0 : -std::expm1(-2.0 * kappa);
  return std::log(kappa / (2.0 * std::numbers::pi * one_minus)) + kappa * (cos_angle - 1.0);
}

double vmf_cos_from_uniform(double kappa, double u) {
  if (kappa < 1e-9) return 1.0 - 2.0 * u;
  return std::clamp(1.0 + std::log1p(u * std::expm1(-2.0 * kappa)) / kappa, -1.0, 1.0);
}

// Below this kappa (or below L^2 / 2) the band factors come from the backward recurrence (vmf_band_factors).
constexpr double kForwardBandFactorsMinKappa = 8.0;

void vmf_band_factors(double kappa, std::span<double> out) {
  if (out.empty()) return;
  const int order = int(out.size()) - 1;
  out[0] = 1.0;
  if (order == 0) return;
  if (!(kappa > 0.0)) {
    std::fill(out.begin() + 1, out.end(), std::isinf(kappa) ? 1.0 : 0.0);
    return;
  }
  if (std::isinf(kappa)) {
    std::fill(out.begin() + 1, out.end(), 1.0);
    return;
  }
  const double top = order + 1.0;
  if (kappa > 1e8 || kappa * kappa * kappa > 5e11 * top * top * top * top) {
    // Hankel's expansion I_nu(k) ~ e^k / sqrt(2 pi k) (1 - (mu - 1) / (8k) + (mu - 1)(mu - 9) / (2 (8k)^2) - ...),
    // mu = 4 nu^2, taken in the log: log I_nu(k) = k - log(2 pi k) / 2 - (mu - 1) / (8k) - (mu - 1) / (16 k^2)
    // + O(mu^2 / k^3). For nu = 1/2 the correction terms vanish, and mu - 1 = 4 l (l + 1) for nu = l + 1/2:
    //     +-------------------------------------------------------------+
    //     | Lambda_l(k) = exp(-l (l + 1) / (2k) - l (l + 1) / (4 k^2))  |
    //     +-------------------------------------------------------------+
    // with a relative error ~ l^4 / (24 k^3): against 40-digit Bessel ratios (mpmath) 4.6e-14 at l = 32, k = 1e6,
    // and 7.8e-14 at the switch for order 32 (k = 8.4e5), where it is largest; there it agrees with the forward
    // recurrence below to 8e-14 (orders 8-128). Tests: VmfLobe.BandFactorsMatchQuadrature (every branch),
    // VmfLobe.BandFactorsLimitsAndAsymptoticSwitch.
    for (int l = 1; l <= order; ++l) {
      const double ll = double(l) * (l + 1);
      out[size_t(l)] = std::exp(-ll / (2.0 * kappa) - ll / (4.0 * kappa * kappa));
    }
    return;
  }
  if (kappa >= kForwardBandFactorsMinKappa && kappa >= 0.5 * order * order) {
    // Forward from the closed forms of the half-integer Bessel functions: Lambda_1 = coth k - 1/k (A(k)), and
    // I_{nu-1} - I_{nu+1} = (2 nu / k) I_nu gives Lambda_{l+1} = Lambda_{l-1} - (2l + 1) / k Lambda_l. I_nu is the
    // recurrence's minimal solution, so forward steps are unstable in general; but for l <= sqrt(2k) the dominant
    // solution K_nu is ~e^-2k smaller relative to I_nu and each step subtracts less than it keeps, so the error
    // stays at rounding: against the backward recurrence within 4e-15 for k >= max(8, L^2 / 2), L <= 128, up to
    // the asymptotic switch (and within 1.1e-14 to 1e7, where the backward recurrence's ~6 sqrt(k) steps carry
    // their own rounding). It costs L steps where the backward one costs ~6 sqrt(k) divisions: up to ~1100 per call
    // for the kappa of a sharp lobe, a quarter of a vmf render's time before. Tests:
    // VmfLobe.BandFactorsMatchQuadrature, VmfLobe.BandFactorsBranchesAgreeWhereTheySwitch.
    out[1] = 1.0 / std::tanh(kappa) - 1.0 / kappa;
    for (int l = 1; l < order; ++l) out[size_t(l) + 1] = out[size_t(l) - 1] - (2.0 * l + 1.0) / kappa * out[size_t(l)];
    return;
  }
  // Backward recurrence rho_l = k / ((2l + 1) + k rho_{l+1}), started at N from Amos's estimate
  // rho_N ~ k / (N + 1/2 + sqrt((N + 1/2)^2 + k^2)). A start error shrinks by ~rho^2 per step, i.e. by
  // exp(-(N^2 - l^2) / k) overall, so N = order + 16 + 6 sqrt(k) leaves < 1e-16.
  const int start = order + 16 + int(std::ceil(6.0 * std::sqrt(kappa)));
  double rho = kappa / (start + 0.5 + std::sqrt((start + 0.5) * (start + 0.5) + kappa * kappa));
  std::vector<double> ratios(size_t(order) + 1);
  for (int l = start; l >= 1; --l) {
    rho = kappa / ((2.0 * l + 1.0) + kappa * rho);
    if (l <= order) ratios[size_t(l)] = rho;
  }
  for (int l = 1; l <= order; ++l) out[size_t(l)] = out[size_t(l) - 1] * ratios[size_t(l)];
}

VmfLobeShape vmf_lobe_from_premultiplied(double alpha, const Vec3& alpha_r, double kappa_max) {
  VmfLobeShape lobe;
  if (!(alpha > 0.0)) return lobe;
  const Vec3 r = alpha_r / alpha;
  const double length = r.norm();
  lobe.alpha = alpha;
  lobe.kappa = vmf_kappa_from_mean_length(length, kappa_max);
  lobe.mu = unit_resultant(r, length);
  return lobe;
}

Vec3 vmf_direction_from_premultiplied(double alpha, const Vec3& alpha_r) {
  const Vec3 r = alpha_r / alpha;
  return unit_resultant(r, r.norm());
}

}  // namespace mbk
