// [Parilov05] Sec. 4.2, constrained Laplacian smoothing of the gradient map: "each vertex moves toward the
// barycenter of its neighbors, excluding the neighbors on the other side of discontinuity" (~10 iterations).
// Neighbours are the four lattice neighbours; one is excluded when the lattice edge joining them has a
// crossing (a discontinuity passes between them). Each iteration (Jacobi, so the result does not depend on
// the thread count) moves g halfway to the barycentre, g <- g + 0.5 (mean - g), and renormalises; a sample
// whose neighbours are all excluded, or whose moved vector is shorter than 1e-12 (opposite neighbours
// cancelling: no direction to renormalise), keeps its vector. The distance itself is never smoothed.
#pragma once

#include <cstdint>

#include "formats/crease_field.h"

namespace mbk {

// Returns the largest angle (radians) any sample's gradient turned over all iterations.
double smooth_gradient(CreaseField& field, uint32_t iterations);

}  // namespace mbk
