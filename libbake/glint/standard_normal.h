// The standard normal distribution N(0, 1) in double precision: density, CDF Phi and its inverse Phi^-1
// (the Gaussian of histogram-preserving blending, [Heitz18] Sec. 3; glint_technique.h).
//
// Accuracy: standard_normal_cdf is 0.5 erfc(-x / sqrt(2)), accurate to a few ulps RELATIVE in the lower tail
// (no cancellation down to Phi = 1e-308, x ~ -37.5); in the upper tail use standard_normal_cdf(-x) for 1 - Phi.
// standard_normal_quantile starts from Acklam's rational approximation (relative error 1.15e-9) and refines it
// with Halley steps on erfc until the correction is below an ulp, so Phi(Phi^-1(p)) = p to the conditioning of
// Phi for p from 1e-300 to 1 - 2^-53 (tests: StandardNormal.*). Lower-tail arguments are used as given and
// p > 1/2 through the exact complement 1 - p, so both tails are symmetric: Phi^-1(1 - q) = -Phi^-1(q).
#pragma once

namespace mbk {

// exp(-x^2 / 2) / sqrt(2 pi).
double standard_normal_pdf(double x);
// Phi(x) = P(X <= x); 0 and 1 at -inf and +inf, NaN for NaN.
double standard_normal_cdf(double x);
// Phi^-1(p): -inf for p <= 0, +inf for p >= 1, NaN for NaN. Subnormal p (< 2.2e-308) lose relative accuracy
// with erfc itself.
double standard_normal_quantile(double p);

}  // namespace mbk
