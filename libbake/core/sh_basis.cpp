// Real spherical harmonics by normalised associated-Legendre recurrences (see sh_basis.h).
#include "libbake/core/sh_basis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "formats/error.h"

namespace mbk {
namespace {

constexpr double kInvSqrt4Pi = 0.28209479177387814347;  // 1 / sqrt(4 pi) = P_0^0
constexpr double kSqrt2 = std::numbers::sqrt2;

}  // namespace

ShBasisEvaluator::ShBasisEvaluator(int order) : order_(order) {
  if (order < 0 || order > kMaxShOrder)
    throw Error(ExitCode::runtime_failure,
                "internal: SH order " + std::to_string(order) + " outside 0.." + std::to_string(kMaxShOrder));
  a_.assign(size_t(count()), 0.0);
  b_.assign(size_t(count()), 0.0);
  diagonal_.assign(size_t(order) + 1, 0.0);
  for (int m = 1; m <= order; ++m) diagonal_[size_t(m)] = std::sqrt((2.0 * m + 1.0) / (2.0 * m));
  for (int m = 0; m <= order; ++m)
    for (int l = m + 2; l <= order; ++l) {
      const double l2 = double(l) * l, m2 = double(m) * m, lm1 = double(l - 1) * (l - 1);
      a_[size_t(sh_index(l, m))] = std::sqrt((4.0 * l2 - 1.0) / (l2 - m2));
      b_[size_t(sh_index(l, m))] = std::sqrt((lm1 - m2) / (4.0 * lm1 - 1.0));
    }
}

void ShBasisEvaluator::evaluate(const Vec3& d, std::span<double> out) const {
  if (out.size() < size_t(count()))
    throw Error(ExitCode::runtime_failure, "internal: SH output span shorter than the basis");
  const double t = std::clamp(d.z(), -1.0, 1.0);
  // sin(theta) from x and y (not sqrt(1 - z^2)), so that it keeps full relative precision near the poles.
  const double s = std::hypot(d.x(), d.y());
  // cos(phi) and sin(phi) of phi = atan2(y, x) without the trigonometric calls (phi = 0 on the pole, where every
  // m > 0 term is 0), and cos(m phi), sin(m phi) by the angle-addition recurrence in m.
  const double cos_phi = s > 0.0 ? d.x() / s : 1.0, sin_phi = s > 0.0 ? d.y() / s : 0.0;
  double cos_m = 1.0, sin_m = 0.0;  // cos(m phi), sin(m phi)
  double pmm = kInvSqrt4Pi;         // P_m^m, updated along the diagonal
  for (int m = 0; m <= order_; ++m) {
    if (m > 0) {
      pmm *= diagonal_[size_t(m)] * s;
      const double next_cos = cos_m * cos_phi - sin_m * sin_phi;
      sin_m = sin_m * cos_phi + cos_m * sin_phi;
      cos_m = next_cos;
    }
    const double c = m == 0 ? 1.0 : kSqrt2 * cos_m, sn = m == 0 ? 0.0 : kSqrt2 * sin_m;
    auto store = [&](int l, double p) {
      if (m == 0) {
        out[size_t(sh_index(l, 0))] = p;
      } else {
        out[size_t(sh_index(l, m))] = p * c;
        out[size_t(sh_index(l, -m))] = p * sn;
      }
    };
    store(m, pmm);
    if (m == order_) break;
    double p_prev = pmm, p = std::sqrt(2.0 * m + 3.0) * t * pmm;  // P_{m+1}^m
    store(m + 1, p);
    for (int l = m + 2; l <= order_; ++l) {
      const size_t k = size_t(sh_index(l, m));
      const double next = a_[k] * (t * p - b_[k] * p_prev);
      p_prev = p;
      p = next;
      store(l, p);
    }
  }
}

std::vector<double> ShBasisEvaluator::evaluate(const Vec3& unit_direction) const {
  std::vector<double> out(static_cast<size_t>(count()));
  evaluate(unit_direction, out);
  return out;
}

void zonal_harmonics(int order, double t, std::span<double> out) {
  if (order < 0 || out.size() < size_t(order) + 1)
    throw Error(ExitCode::runtime_failure, "internal: zonal harmonic output span too short");
  t = std::clamp(t, -1.0, 1.0);
  out[0] = kInvSqrt4Pi;
  if (order == 0) return;
  out[1] = std::sqrt(3.0) * t * kInvSqrt4Pi;
  for (int l = 2; l <= order; ++l) {
    const double l2 = double(l) * l, lm1 = double(l - 1) * (l - 1);
    const double a = std::sqrt((4.0 * l2 - 1.0) / l2), b = std::sqrt(lm1 / (4.0 * lm1 - 1.0));
    out[size_t(l)] = a * (t * out[size_t(l) - 1] - b * out[size_t(l) - 2]);
  }
}

}  // namespace mbk
