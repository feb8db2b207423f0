// The half vector's sweep over a pixel as cells (see pixel_sweep.h).
#include "libbake/glint/pixel_sweep.h"

#include <algorithm>
#include <cmath>

namespace mbk {

SweptNormals pixel_sweep(const Vec2& s, const Mat2& steps, double sigma_r) {
  if (!steps.allFinite()) return {{s}, Mat2::Zero()};
  int cells[2];
  for (int k = 0; k < 2; ++k)
    cells[k] =
        int(std::clamp(std::ceil(steps.col(k).norm() / (kSweepCellSigmas * sigma_r)), 1.0, double(kMaxSweepCells)));
  while (cells[0] * cells[1] > kMaxSweepNormals) --cells[cells[0] >= cells[1] ? 0 : 1];
  SweptNormals out;
  out.normals.reserve(size_t(cells[0] * cells[1]));
  for (int j = 0; j < cells[1]; ++j)
    for (int i = 0; i < cells[0]; ++i)
      out.normals.push_back(s + ((i + 0.5) / cells[0] - 0.5) * steps.col(0) +
                            ((j + 0.5) / cells[1] - 0.5) * steps.col(1));
  for (int k = 0; k < 2; ++k) {
    const Vec2 cell = steps.col(k) / cells[k];
    out.residual += cell * cell.transpose() / 12.0;
  }
  out.residual = 0.5 * (out.residual + out.residual.transpose());  // exactly symmetric
  return out;
}

}  // namespace mbk
