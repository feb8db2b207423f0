// Tileable noise for the procedural generators: gradient (Perlin-style) noise on a lattice that wraps
// after a whole number of cells, and its fractal sum. Lattice gradients come from integer hashes
// (libbake/core/hash.h) and the arithmetic is plain IEEE double (no sin/cos/exp), so values are identical
// on every compiler and thread count.
// Reference: K. Perlin, "Improving Noise", SIGGRAPH 2002 (quintic fade, fixed gradient set).
#pragma once

#include <cstdint>

#include "libbake/core/eigen.h"

namespace mbk {

// Gradient noise at lattice coordinates (x, y), periodic with period_x x period_y cells (both >= 1);
// roughly in [-1, 1], zero at lattice points, C2-continuous.
double periodic_gradient_noise(double x, double y, uint32_t period_x, uint32_t period_y, uint32_t seed);

// Fractal sum over octaves o = 0 .. octaves-1 of gain^o * noise at cells * 2^o, evaluated at uv in [0, 1)^2;
// periodic in uv with period 1 on both axes, so a map sampled at texel centres tiles.
double periodic_fbm(const Vec2& uv, uint32_t cells_x, uint32_t cells_y, int octaves, double gain, uint32_t seed);

// How many of `wanted` octaves starting at `cells` cells keep at least two texels per cell on an axis of
// `texels` texels (finer octaves would alias). At least 1.
int octaves_resolved(uint32_t cells, uint32_t texels, int wanted);

}  // namespace mbk
