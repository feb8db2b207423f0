// Stratified, hash-jittered sub-pixel samples (see pixel_samples.h).
#include "libbake/eval/pixel_samples.h"

#include "libbake/core/hash.h"

namespace mbk {

SampleGrid sample_grid(uint32_t count) {
  uint32_t rows = 1;
  for (uint32_t r = 1; uint64_t(r) * r <= count; ++r)
    if (count % r == 0) rows = r;
  return {count / rows, rows};
}

Vec2 sample_offset(uint32_t x, uint32_t y, uint32_t index, const SampleGrid& grid, uint32_t seed) {
  const uint32_t i = index % grid.cols, j = index / grid.cols, stream = 2 * seed;
  return Vec2((i + unit_from_hash(hash4(x, y, index, stream))) / grid.cols,
              (j + unit_from_hash(hash4(x, y, index, stream + 1))) / grid.rows);
}

Vec2 cell_centre(uint32_t index, const SampleGrid& grid) {
  return Vec2((index % grid.cols + 0.5) / grid.cols, (index / grid.cols + 0.5) / grid.rows);
}

}  // namespace mbk
