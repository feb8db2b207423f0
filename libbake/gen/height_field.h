// Periodic height fields and the normal maps derived from them. Heights are in texel units (a height
// change of 1 over one texel is a 45-degree slope). Slopes are central differences on the periodic grid,
//   dh/dx = (h[x+1] - h[x-1]) / 2,   dh/dy = (h[row-1] - h[row+1]) / 2   (tangent y is up, rows go down),
// and the normal is normalize(-s dh/dx, -s dh/dy, 1) for a scale s. Central differences commute on a
// periodic grid, so the slope field (-nx/nz, -ny/nz) has zero discrete curl: the maps are integrable (they
// are the normals of a real surface) and tile. tests/gen checks both.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "libbake/core/progress.h"
#include "libbake/image/normal_map.h"

namespace mbk {

struct HeightField {
  uint32_t width = 0, height = 0;
  std::vector<double> h;  // row-major, row 0 at the top
  double at(uint32_t x, uint32_t row) const { return h[size_t(row) * width + x]; }
};

// Evaluates height(x, row) at every texel (in parallel over rows; advances `progress` by one per row).
HeightField sample_height_field(uint32_t width, uint32_t height,
                                const std::function<double(uint32_t x, uint32_t row)>& fn, Progress& progress);

// The texel centre of (x, row) in uv (normal_map.h): ((x + 0.5) / W, 1 - (row + 0.5) / H).
Vec2 texel_uv(uint32_t x, uint32_t row, uint32_t width, uint32_t height);

// Root-mean-square length of the central-difference gradient; 0 for a constant field.
double rms_slope(const HeightField& field);

// Unit normals of the field scaled by `scale` (see above).
NormalMap normals_from_height(const HeightField& field, double scale);

// The same with the scale that gives an RMS slope of `target` (a flat map for a constant field), so that a
// generator's look does not depend on the resolution it is sampled at.
NormalMap normals_with_rms_slope(const HeightField& field, double target);

}  // namespace mbk
