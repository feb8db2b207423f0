// The half vector's sweep over a pixel, for a renderer that evaluates the P-NDF once per pixel (glint_pndf.h,
// "Directional spread"): where s = (h . T, h . B) goes as the shading point moves over the pixel.
//
// With S = ds/d(pixel) the 2 x 2 Jacobian of s over the pixel's two steps (columns), a box pixel spreads s
// uniformly over the parallelogram S [-1/2, 1/2]^2 around the centre's s. A Gaussian of the box's covariance
// S S^T / 12 stands in for it badly when a highlight is narrower than the sweep: pixel by pixel the Gaussian puts
// the light where the box does not reach, and summed over pixels its samples of a narrow Gaussian (spaced one
// sweep apart, 3.5 of its deviations) are a Riemann sum that misses by up to 40% with the highlight's phase
// (measured: a sub-pixel highlight at 6 degrees came out 12-45% dark). So the parallelogram is cut into
// M_x x M_y cells, each no longer than kSweepCellSigmas sigma_r along its step (M_k <= kMaxSweepCells, their
// product <= kMaxSweepNormals), D_P is averaged over the cells' centres, and each cell keeps the covariance of
// its own box, sum_k (S_k / M_k)(S_k / M_k)^T / 12, as the sweep of the elements (GlintFootprint::sweep).
// Gaussians of deviation >= sigma_r spaced <= 2 sigma_r apart sum to a constant within 2 exp(-2 pi^2 / 4) = 1.4%,
// so the average is the box's up to that ripple.
#pragma once

#include <vector>

#include "libbake/core/eigen.h"

namespace mbk {

inline constexpr double kSweepCellSigmas = 2.0;
inline constexpr int kMaxSweepCells = 8;
inline constexpr int kMaxSweepNormals = 32;

struct SweptNormals {
  std::vector<Vec2> normals;     // the cells' centres in s
  Mat2 residual = Mat2::Zero();  // each cell's sweep covariance
};

// The cells of the sweep of s over a pixel with Jacobian `steps` (columns: ds per pixel step x and y) for
// elements of intrinsic roughness sigma_r > 0. Non-finite steps (grazing rays) give s alone with no sweep.
SweptNormals pixel_sweep(const Vec2& s, const Mat2& steps, double sigma_r);

}  // namespace mbk
