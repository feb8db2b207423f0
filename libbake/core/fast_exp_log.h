// exp and log for the vMF E-step's log-sum-exp (libbake/filter/vmf_e_step.h), for a double or a GCC vector of
// doubles (D, with U the unsigned 64-bit integers of its width): no branches, no calls, integer work on the bits
// only (shifts, adds, masks), the same operations in every lane, so a vector lane gives the scalar's bits. Each is
// accurate to ~2 ulp on its domain (tests: FastExpLog.*, against std::exp / std::log).
//
// fast_exp(d), d in [-64, 0]: Cody-Waite reduction d = k ln2 + r with k = round(d / ln2) (by adding and subtracting
// 1.5 2^52) and ln2 split in a 32-bit head (k ln2_hi exact) and its tail, |r| <= ln2 / 2; e^r by its Taylor series
// to r^13 / 13! (truncation < 2e-16 relative); 2^k put into the exponent field from the rounded k's low bits.
// fast_log(s), s positive and normal: s = 2^e m with m in [sqrt(1/2), sqrt(2)), log m = 2 atanh(f) with
// f = (m - 1) / (m + 1), |f| <= 0.1716, by its series to f^21 (truncation < 1e-17 relative), plus e ln2.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

namespace mbk {

// 1 / n!, n = 13 down to 0: e^r to r^13, highest power first.
inline constexpr double kExpTaylor[] = {1.0 / 6227020800.0,
                                        1.0 / 479001600.0,
                                        1.0 / 39916800.0,
                                        1.0 / 3628800.0,
                                        1.0 / 362880.0,
                                        1.0 / 40320.0,
                                        1.0 / 5040.0,
                                        1.0 / 720.0,
                                        1.0 / 120.0,
                                        1.0 / 24.0,
                                        1.0 / 6.0,
                                        0.5,
                                        1.0,
                                        1.0};
// 1 / (2n + 1), n = 10 down to 0: atanh(f) / f in powers of f^2, highest first.
inline constexpr double kAtanhSeries[] = {1.0 / 21.0, 1.0 / 19.0, 1.0 / 17.0, 1.0 / 15.0, 1.0 / 13.0, 1.0 / 11.0,
                                          1.0 / 9.0,  1.0 / 7.0,  1.0 / 5.0,  1.0 / 3.0,  1.0};

// sum c_i x^(n-i) by Horner's rule, for a double or a vector.
template <typename D, size_t N>
[[gnu::always_inline]] inline D horner(D x, const double (&c)[N]) {
  D p = D{} + c[0];
  for (size_t i = 1; i < N; ++i) p = p * x + c[i];
  return p;
}

template <typename D = double, typename U = uint64_t>
[[gnu::always_inline]] inline D fast_exp(D d) {
  constexpr double kInvLn2 = 0x1.71547652b82fep0, kShift = 0x1.8p52;
  constexpr double kLn2Hi = 0x1.62e42feep-1, kLn2Lo = 0x1.a39ef35793c76p-33;
  const D t = d * kInvLn2 + kShift, k = t - kShift;
  const D r = (d - k * kLn2Hi) - k * kLn2Lo;
  const D p = horner(r, kExpTaylor);
  // The low bits of t hold k (two's complement); 2^k has the biased exponent k + 1023.
  const U k_bits = std::bit_cast<U>(t) - std::bit_cast<uint64_t>(kShift);
  return p * std::bit_cast<D>((k_bits + 1023u) << 52);
}

template <typename D = double, typename U = uint64_t>
[[gnu::always_inline]] inline D fast_log(D s) {
  constexpr double kLn2Hi = 0x1.62e42feep-1, kLn2Lo = 0x1.a39ef35793c76p-33, kSqrt2 = 0x1.6a09e667f3bcdp0;
  const U bits = std::bit_cast<U>(s);
  // The biased exponent as a double (placed in the mantissa of 2^52), and the mantissa in [1, 2).
  const D biased = std::bit_cast<D>((bits >> 52) | 0x4330000000000000u) - 0x1p52;
  const D mantissa = std::bit_cast<D>((bits & 0x000fffffffffffffu) | 0x3ff0000000000000u);
  const auto high = mantissa > kSqrt2;
  const D m = high ? 0.5 * mantissa : mantissa, e = biased - (high ? 1022.0 : 1023.0);
  const D f = (m - 1.0) / (m + 1.0), f2 = f * f;
  const D p = horner(f2, kAtanhSeries);
  return e * kLn2Hi + (2.0 * f * p + e * kLn2Lo);
}

}  // namespace mbk
