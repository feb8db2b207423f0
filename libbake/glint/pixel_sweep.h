// The pixel cut into sub-pixel cells for the half vector's sweep (glint_pndf.h, "The half vector's slope field"),
// for a renderer that shades a pixel once with a Gaussian footprint.
//
// Within a footprint the slope field ties each point to its own half vector exactly, but the footprint is a
// Gaussian of the pixel box's deviation, not the box: a highlight narrower than the pixel's sweep (a flat map's
// mirror image of a point light) is then weighted by that Gaussian across the pixel, and summed over pixels its
// samples (spaced one pixel apart, 3.5 of the Gaussian's deviations) are a Riemann sum that misses by up to 40%
// with the highlight's phase (measured: a sub-pixel highlight at 6 degrees came out 12-45% dark). So the pixel is
// cut into M_x x M_y sub-pixel cells, each sweeping s by at most kSweepCellSigmas sigma_r along its step
// (M_k <= kMaxSweepCells, their product <= kMaxSweepCells), each with its own footprint, its own half vector at its
// centre and the slope field: a highlight of deviation >= sigma_r seen through cells whose sweep is <= 2 sigma_r
// is a sum of Gaussians spaced <= 2 sigma_r apart, constant within 2 exp(-2 pi^2 / 4) = 1.4%, so the pixel's mean
// over its cells is the box's up to that ripple.
#pragma once

#include <array>

#include "libbake/core/eigen.h"

namespace mbk {

inline constexpr double kSweepCellSigmas = 2.0;
inline constexpr int kMaxSweepCells = 8;
inline constexpr int kMaxSweepCellsPerPixel = 32;

// How many cells per pixel step (x, y) for a pixel over which s moves by the columns of `steps`, for elements of
// intrinsic roughness sigma_r > 0. Non-finite steps (grazing rays) give one cell.
std::array<int, 2> pixel_sweep_cells(const Mat2& steps, double sigma_r);

}  // namespace mbk
