// Tileable cellular structure (see periodic_cells.h).
//
// Why 5 x 5 cells are enough: the query point q lies in cell c, whose feature point is within sqrt(2) < 2
// of q. Every cell outside the 5 x 5 block around c is at least 2 cells away from q, so it cannot hold the
// nearest feature point.
#include "libbake/gen/periodic_cells.h"

#include <cmath>

#include "libbake/core/hash.h"

namespace mbk {

namespace {

// The feature point of lattice cell (i, j) (unwrapped: the point moves with the cell's copy).
Vec2 feature_point(int64_t i, int64_t j, uint32_t cells_x, uint32_t cells_y, double jitter, uint32_t seed,
                   uint64_t& key) {
  const uint32_t wi = uint32_t(((i % cells_x) + cells_x) % cells_x);
  const uint32_t wj = uint32_t(((j % cells_y) + cells_y) % cells_y);
  const uint32_t h = hash3(seed, wi, wj);
  key = (uint64_t(wj) << 32) | wi;
  return {double(i) + 0.5 + jitter * (unit_from_hash(h) - 0.5),
          double(j) + 0.5 + jitter * (unit_from_hash(pcg_hash(h)) - 0.5)};
}

}  // namespace

CellQuery nearest_cells(const Vec2& uv, uint32_t cells_x, uint32_t cells_y, double jitter, uint32_t seed) {
  const Vec2 q(uv.x() * cells_x, uv.y() * cells_y);
  const int64_t cx = int64_t(std::floor(q.x())), cy = int64_t(std::floor(q.y()));
  CellQuery best;
  double d1 = INFINITY;  // squared
  uint64_t key1 = UINT64_MAX;
  Vec2 nearest = Vec2::Zero();
  for (int64_t j = cy - 2; j <= cy + 2; ++j)
    for (int64_t i = cx - 2; i <= cx + 2; ++i) {
      uint64_t key;
      const Vec2 p = feature_point(i, j, cells_x, cells_y, jitter, seed, key);
      const double d = (p - q).squaredNorm();
      if (d < d1 || (d == d1 && key < key1)) {
        d1 = d, key1 = key, nearest = p;
        best.cell_x = uint32_t(key & 0xffffffffu), best.cell_y = uint32_t(key >> 32);
      }
    }
  best.f1 = std::sqrt(d1);
  // Distance to the bisector between the nearest point n and another point p, measured towards p:
  // (|q - p|^2 - |q - n|^2) / (2 |p - n|). The cell's nearest edge is the smallest over all p. Points that
  // coincide with n (possible only with jitter 0 and tiny lattices) have no bisector.
  best.border = INFINITY;
  for (int64_t j = cy - 2; j <= cy + 2; ++j)
    for (int64_t i = cx - 2; i <= cx + 2; ++i) {
      uint64_t key;
      const Vec2 p = feature_point(i, j, cells_x, cells_y, jitter, seed, key);
      const double gap = (p - nearest).norm();
      if (gap == 0.0) continue;
      best.border = std::min(best.border, ((q - p).squaredNorm() - d1) / (2.0 * gap));
    }
  return best;
}

}  // namespace mbk
