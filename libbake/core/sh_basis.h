// The real spherical-harmonic basis of every technique in microbake, to any order (tested to l = 128):
// lighting (libbake/eval/sh_lighting.h, order 2) and NDF pyramids ([Han07] Sec. 7.4, libbake/filter/).
//
// Conventions (stated once here):
// - Order L means bands l = 0..L, (L + 1)^2 functions. Index k = l (l + 1) + m, m = -l..l.
// - Real, orthonormal over the unit sphere (integral of Y_lm Y_l'm' dOmega = delta), no Condon-Shortley
//   phase, evaluated on unit directions (x, y, z) with theta measured from +z and phi = atan2(y, x):
//     Y_l0 = P_l^0(cos theta),  Y_lm = sqrt(2) P_l^m(cos theta) cos(m phi),
//     Y_l,-m = sqrt(2) P_l^m(cos theta) sin(m phi)  (m > 0),
//   where P_l^m are the normalised associated Legendre functions
//     P_l^m = sqrt((2l + 1) / (4 pi) (l - m)! / (l + m)!) P_l^m[classical, no (-1)^m].
//   So Y00 = 1 / (2 sqrt(pi)), (Y1-1, Y10, Y11) = sqrt(3 / (4 pi)) (y, z, x), Y2-2 = sqrt(15 / (4 pi)) x y...
// - Evaluation never forms factorials (they overflow past l + m ~ 170): P_l^m comes from the normalised
//   three-term recurrences, in double:
//     P_0^0 = 1 / sqrt(4 pi),  P_m^m = sqrt((2m + 1) / (2m)) sin(theta) P_{m-1}^{m-1},
//     P_{m+1}^m = sqrt(2m + 3) cos(theta) P_m^m,
//     P_l^m = a_lm (cos(theta) P_{l-1}^m - b_lm P_{l-2}^m),
//     a_lm = sqrt((4 l^2 - 1) / (l^2 - m^2)),  b_lm = sqrt(((l - 1)^2 - m^2) / (4 (l - 1)^2 - 1)).
//   Every value is bounded by sqrt((2l + 1) / (4 pi)) (|Y_lm| <= sqrt((2l+1)/(2 pi)) for m != 0), so nothing
//   overflows; near the poles sin(theta)^m may underflow to 0, which is then the correctly rounded value.
//   cos(m phi) and sin(m phi) come from cos phi = x / sin(theta), sin phi = y / sin(theta) by angle addition
//   in m (no trigonometric call; the rounding error grows ~m ulp, 3e-14 relative at m = 128).
#pragma once

#include <span>
#include <vector>

#include "libbake/core/eigen.h"

namespace mbk {

// Largest order the basis accepts (a bound for sane allocation sizes, not for accuracy).
inline constexpr int kMaxShOrder = 256;

constexpr int sh_count(int order) { return (order + 1) * (order + 1); }
constexpr int sh_index(int l, int m) { return l * (l + 1) + m; }

// Precomputed recurrence factors for one order; evaluating many directions reuses them.
class ShBasisEvaluator {
 public:
  // 0 <= order <= kMaxShOrder, else Error(runtime_failure).
  explicit ShBasisEvaluator(int order);
  int order() const { return order_; }
  int count() const { return sh_count(order_); }
  // Writes Y_k(d) for k < count() into out (out.size() >= count()). d must be unit length (not checked:
  // a non-unit d gives the basis at d / |d| only for the phi part; callers normalise).
  void evaluate(const Vec3& unit_direction, std::span<double> out) const;
  std::vector<double> evaluate(const Vec3& unit_direction) const;

 private:
  int order_;
  std::vector<double> a_, b_;     // a_lm, b_lm at index sh_index(l, m) for m >= 0
  std::vector<double> diagonal_;  // sqrt((2m + 1) / (2m)) for m >= 1
};

// The zonal harmonic Y_l0 at cos(theta) = t, for l = 0..order (the same recurrence with m = 0).
void zonal_harmonics(int order, double t, std::span<double> out);

}  // namespace mbk
