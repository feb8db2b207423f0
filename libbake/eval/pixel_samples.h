// Stratified sub-pixel sample positions. `count` samples sit on a cols x rows grid (rows = the largest
// divisor of count not above sqrt(count), so 16 -> 4 x 4, 8 -> 4 x 2, 7 -> 7 x 1), one per cell, jittered
// inside its cell by PCG hashes of (pixel x, pixel y, sample index, 2 seed + axis) (libbake/core/hash.h). A
// pixel's samples depend only on its coordinates and the seed, so images are identical whatever --threads is;
// another seed gives independent jitter (what `render --seed` varies to measure a reference's noise floor).
#pragma once

#include <cstdint>

#include "libbake/core/eigen.h"

namespace mbk {

struct SampleGrid {
  uint32_t cols = 1, rows = 1;
  uint32_t count() const { return cols * rows; }
};

SampleGrid sample_grid(uint32_t count);
// Offset in [0, 1)^2 inside pixel (x, y) of sample `index` < grid.count().
Vec2 sample_offset(uint32_t x, uint32_t y, uint32_t index, const SampleGrid& grid, uint32_t seed = 0);
// The centre of cell `index` < grid.count(), the same cell order as sample_offset.
Vec2 cell_centre(uint32_t index, const SampleGrid& grid);

}  // namespace mbk
