// SH NDF pyramids: [Han07] Sec. 7.4.1, "Computing NDF coefficients". The NDF of a MIP texel q is the
// distribution of the finest normals it covers, g(n) = sum_i w_i delta(n - n_i) (w_i the area weights of
// formats/mip_levels.h, summing to 1), and its real SH coefficients (libbake/core/sh_basis.h) are
//     g_lm(q) = sum_i w_i Y_lm(n_i),
// the weighted mean of Y_lm over the covered normals. At the finest level g_lm = Y_lm(n), so that level is
// represented by the normals themselves (the evaluator computes Y_lm(n)); levels 1..K-1 hold coefficients.
// Because the coefficients are linear in the NDF, a level whose texels each cover exactly 2 x 2 (or 2 x 1,
// 1 x 2) texels of the level below is the plain box mean of those (exact); a level that does not nest (an odd
// size on the way, e.g. 7 -> 3) is computed from the finest normals directly with the partial-coverage
// weights, so every texel is exactly the mean over its rectangle whatever the size.
#pragma once

#include <cstdint>
#include <vector>

#include "formats/mip_levels.h"
#include "libbake/core/progress.h"
#include "libbake/image/normal_map.h"

namespace mbk {

struct ShLevel {
  uint32_t width = 0, height = 0;
  std::vector<float> coefficients;  // [height][width][(order + 1)^2], row 0 at the top
  const float* texel(uint32_t x, uint32_t row, int count) const {
    return &coefficients[(size_t(row) * width + x) * size_t(count)];
  }
};

struct ShPyramid {
  int order = 0;
  std::vector<ShLevel> levels;  // levels[k - 1] is MIP level k (level 0 is the normal map itself)
};

// Receives the coefficient rows of levels 1..K-1 as they are computed, so that a bake converts and stores them
// without holding the largest level in f32 (at 2048^2, order 8, level 1 is 340 MiB in f32).
class ShRowSink {
 public:
  virtual ~ShRowSink() = default;
  // Called once, before any row: levels[k - 1] is the size of level k; count coefficients per texel.
  virtual void start(const std::vector<LevelSize>& levels, int count) = 0;
  // Row `row` of level k >= 1: width * count coefficients, texel-major. Called from any thread, every row of
  // every level exactly once, in no particular order; the pointer is valid during the call only.
  virtual void take_row(size_t k, uint32_t row, const float* coefficients) = 0;
};

// Computes the pyramid into `sink`. Memory: level 1 is never held whole; the levels that nest in turn above it
// (up to 4 more, while the top one keeps 64 rows) are built in the same pass, each group of level-1 rows under a
// row of the top level giving its rows of every level, and only the top level is held whole in f32 for the next
// (at 2048^2, order 8: levels 1..5, and 1.3 MiB held instead of level 2's 85 MiB).
// Deterministic whatever the thread count (per-row results, accumulated in double, stored in float).
// Error(runtime_failure) for an order outside 0..kMaxShOrder.
void stream_sh_pyramid(const NormalMap& map, int order, ShRowSink& sink, Progress& progress);

// The whole pyramid in f32 (stream_sh_pyramid into memory).
ShPyramid build_sh_pyramid(const NormalMap& map, int order, Progress& progress);

}  // namespace mbk
