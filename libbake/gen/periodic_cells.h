// Tileable cellular (Worley/Voronoi) structure for the generators: one feature point per lattice cell,
// jittered by an integer hash, on a lattice that wraps after cells_x x cells_y cells. Distances are in
// cell units. Ties between equidistant feature points go to the smaller (row, column) cell index, so the
// result never depends on evaluation order.
// Reference: S. Worley, "A Cellular Texture Basis Function", SIGGRAPH 1996.
#pragma once

#include <cstdint>

#include "libbake/core/eigen.h"

namespace mbk {

struct CellQuery {
  uint32_t cell_x = 0, cell_y = 0;  // wrapped lattice index of the nearest feature point (identifies the cell)
  double f1 = 0.0;                  // distance to the nearest feature point
  double border = 0.0;              // distance to the nearest cell edge: the closest bisector between the
                                    // nearest point and the other points of the 5 x 5 neighbourhood
};

// uv in [0, 1)^2 (periodic); jitter in [0, 1] is how far a feature point may move from its cell centre
// (1 = anywhere in the cell). The 5 x 5 neighbourhood searched makes f1 exact for any jitter.
CellQuery nearest_cells(const Vec2& uv, uint32_t cells_x, uint32_t cells_y, double jitter, uint32_t seed);

}  // namespace mbk
