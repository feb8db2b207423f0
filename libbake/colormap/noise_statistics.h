// Footprint statistics of procedural noise for colour-map filtering ([Heitz13] Sec. 4.2: "for procedural noise
// functions we precompute the noise standard deviation for different levels of detail and store it in a 1D
// texture"): the law of the fractal gradient noise of libbake/gen/periodic_noise.h (the driver the evaluator's
// `colormap` effect can use) over an axis-aligned box footprint, as a Gaussian N(mean, variance).
//
// The process. One octave is N(x) = sum over lattice corners c of K(x_1 - c_1) K(x_2 - c_2) g_c . (x - c), with
// K(t) = 1 - fade(|t|) on |t| < 1 (fade(t) = 6t^5 - 15t^4 + 10t^3, so the bilinear-with-fade interpolation of the
// corner ramps is exactly this sum) and g_c drawn by a hash from 8 gradients (axes and diagonals) with E[g] = 0 and
// E[g g^T] = (3/4) I. Corners carry independent gradients, so every second moment is a sum over corners, and each
// corner's term factors into the two axes. For a box of w_1 x w_2 lattice cells at a uniformly random offset:
//     E[B^2]       = (3/4) (a(w_1) b(w_2) + b(w_1) a(w_2))        (B the box mean of N)
//     E[B N(ctr)]  = (3/4) (a'(w_1) b'(w_2) + b'(w_1) a'(w_2))    (N at the box centre)
//     V = E[N^2]   = (3/4) 2 a(0) b(0),  a(0) = int K^2 t^2 dt,  b(0) = int K^2 dt,
// with the per-axis functions (x0 the box start, uniform in [0, 1); sums over integer c)
//     a(w)  = E[sum_c (int_box K(t - c) (t - c) dt)^2] / w^2,    b(w)  = E[sum_c (int_box K(t - c) dt)^2] / w^2,
//     a'(w) = E[sum_c K(x_c - c)(x_c - c) int_box K(t - c)(t - c) dt] / w,   b'(w) = E[sum_c K(x_c - c) int_box K] / w.
// The box integrals are closed-form polynomials (antiderivatives of K and t K); the expectations over x0 are
// composite Gauss-Legendre. For w >= 4, a' = 0 and b' = 1/w exactly (partition of unity and odd t K); a and b are
// tabulated up to 256 cells and continued by their asymptotes a ~ 1/w^2, b ~ 1/w beyond.
//
// The filtering distribution (our choice; the paper does not say how it gets the footprint mean of noise). Per
// octave, the best linear predictor of the footprint mean from the noise value at the footprint centre is
// kappa N(ctr), kappa = E[B N(ctr)] / V, and given N(ctr) the law of the noise within the footprint has variance
// V (1 - kappa^2) (what is unknown of the footprint mean plus the spread inside it; both vanish as the footprint
// shrinks and tend to V, with mean 0, as it grows). Octaves are independent (separate seeds), so for the fractal
// sum f = sum_o gain^o N_o:  mean = sum_o gain^o kappa_o N_o(ctr),  variance = sum_o gain^(2o) V (1 - kappa_o^2).
// One noise evaluation per octave, as the unfiltered noise costs.
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/core/eigen.h"

namespace mbk {

// The per-axis functions of one octave, tabulated over log2 w (the "1D texture").
class NoiseFootprintTable {
 public:
  NoiseFootprintTable();  // builds the table (a few milliseconds)
  double point_variance() const { return point_variance_; }
  // E[B^2] and E[B N(ctr)] for a w_1 x w_2 box in lattice cells (w >= 0; w = 0 is a point).
  double box_mean_variance(double w1, double w2) const;
  double box_centre_covariance(double w1, double w2) const;

  struct Axis {
    double a, b, a_centre, b_centre;
  };
  // The per-axis functions at w (interpolated in log2 w; linear in w from the point limit below 2^-10, asymptotes
  // above 256).
  Axis axis(double w) const;
  // The same computed directly (no table), for tests.
  static Axis axis_exact(double w);

 private:
  std::vector<Axis> table_;
  Axis zero_{};  // the point limit w = 0
  double point_variance_ = 0.0;
};

struct NoiseParameters {
  uint32_t cells_x = 8, cells_y = 8;
  int octaves = 4;
  double gain = 0.5;
  uint32_t seed = 1;
};

struct NoiseFootprint {
  double mean = 0.0, variance = 0.0;
};

// The Gaussian statistics of periodic_fbm(uv, ...) over an axis-aligned box of box_uv = (width, height) in uv
// centred at uv (see above).
NoiseFootprint fbm_footprint(const NoiseFootprintTable& table, const NoiseParameters& noise, const Vec2& uv,
                             const Vec2& box_uv);

}  // namespace mbk
