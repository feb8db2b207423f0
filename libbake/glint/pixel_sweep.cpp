// The pixel cut into sub-pixel cells for the half vector's sweep (see pixel_sweep.h).
#include "libbake/glint/pixel_sweep.h"

#include <algorithm>
#include <cmath>

namespace mbk {

std::array<int, 2> pixel_sweep_cells(const Mat2& steps, double sigma_r) {
  if (!steps.allFinite()) return {1, 1};
  std::array<int, 2> cells{};
  for (int k = 0; k < 2; ++k)
    cells[size_t(k)] =
        int(std::clamp(std::ceil(steps.col(k).norm() / (kSweepCellSigmas * sigma_r)), 1.0, double(kMaxSweepCells)));
  while (cells[0] * cells[1] > kMaxSweepCellsPerPixel) --cells[cells[0] >= cells[1] ? 0 : 1];
  return cells;
}

}  // namespace mbk
