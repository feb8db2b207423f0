// The bands an SH NDF of order L does not store, completed from one vMF lobe ([Han07] Eq. 7.12 and Eq. 7.14).
// The SH effect shades D(h) = sum_l rhat_l g_l . Y_l(h): the BRDF lobe's zonal coefficients rhat_l times the
// footprint's NDF coefficients g_lm. Cut at the stored order L, the sum smears and rings wherever the NDF is
// sharp (a magnified or near surface: a few normals per footprint) and the lobe narrow - the near-sphere column of
// the filtering report (order 8 worse than plain mip by 8x). A window only trades the ringing for blur.
//
// The missing bands are completed as those of the vMF lobe with the footprint's mean normal: for an NDF
// g_lm = Lambda_l(kappa) Y_lm(mu), the addition theorem gives the bands beyond L in closed form,
//     tail(h) = sum_{l > L} rhat_l Lambda_l(kappa) (2l + 1) / (4 pi) P_l(h . mu),
// with mu = E[n] / |E[n]| and kappa = A^-1(|E[n]|) (the NDF's first moment, as Toksvig reads it). So
//     D(h) = sum_{l <= L} rhat_l g_l . Y_l(h) + tail(h)
// is exact for one normal (kappa = inf: the full series of the lobe) and for any vMF NDF, equals the stored
// expansion where the NDF is broad (Lambda_l(kappa) small past L), and tends to it as L grows. The stored part is
// not windowed (the tail completes it). tail is tabulated per material over the angle to mu (1024 steps on
// [0, pi]) and log kappa (96 steps on [1e-2, 1e8], plus kappa = inf), the bands summed to 8 / alpha (at least
// 4 L + 4, at most 2048).
#pragma once

#include <vector>

#include "libbake/eval/microfacet_brdf.h"

namespace mbk {

class ShLobeTail {
 public:
  ShLobeTail(const MicrofacetLobe& lobe, int order);
  // tail(h) for cos_angle = h . mu and the lobe's kappa = A^-1(|E[n]|) (vmf_kappa_from_mean_length with an
  // infinite cap: one normal gives kappa = inf).
  double value(double cos_angle, double kappa) const;

 private:
  std::vector<double> table_;  // [kappa row][angle], the last row kappa = inf
};

}  // namespace mbk
