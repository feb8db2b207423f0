// The intrinsic-roughness lobe of the histogram effect ([Shah24] Eq. 2's G_r): the spherical Gaussian (von
// Mises-Fisher lobe, libbake/core/vmf_lobe.h)
//     G_r(w; mu, sigma) = kappa / (2 pi (1 - e^{-2 kappa})) e^{kappa (w.mu - 1)},   kappa = 1 / sigma^2,
// normalised over the sphere; for small sigma it is the Gaussian e^{-theta^2 / (2 sigma^2)} / (2 pi sigma^2) of the
// angle theta between w and mu. Roughness sigma is in (0, 1] as in the paper, clamped below at kMinLobeRoughness.
#pragma once

#include "libbake/core/eigen.h"

namespace mbk {

inline constexpr double kMinLobeRoughness = 1e-3;  // sigma below this is taken as this (a finite lobe)

// kappa = 1 / sigma^2 of the lobe, sigma clamped to [kMinLobeRoughness, 1] (NaN as 1).
double lobe_kappa(double sigma);
// G_r(w; mu, sigma) from cos = w . mu.
double roughness_lobe(double cos_angle, double sigma);
// A direction drawn from G_r(.; mu, sigma) by two uniform numbers in [0, 1): exact inversion of the vMF's
// cos-angle distribution, cos = 1 + log(1 + u1 (e^{-2 kappa} - 1)) / kappa, and a uniform azimuth u2.
Vec3 sample_roughness_lobe(const Vec3& mu, double sigma, double u1, double u2);

}  // namespace mbk
