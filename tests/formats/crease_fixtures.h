// Test fixtures for the `crease` kind: a small valid asset built by hand (independently of the bake): a 3 x 2
// flat map cut by the vertical line x = 1.7, which crosses the top and bottom edges of the cells of column 2
// (lattice x in [1.5, 2.5]) at t = 0.2; distances |x - 1.7|, gradients (+-1, 0), sides +-1. Corruptions
// edit the field before writing it, one per crease finding (tests/formats/corrupt_fixtures_test.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "formats/asset_writer.h"
#include "formats/crease_field.h"

namespace mbk::test {

inline CreaseField valid_crease_field() {
  CreaseField f;
  f.allocate(3, 2);
  for (size_t k = 0; k < 6; ++k) f.normals[3 * k + 2] = 1.0f;
  for (uint32_t j = 0; j < f.samples_y(); ++j) {
    f.crossing_h[f.h_edge_index(2, j)] = 0.2f;  // edge from x = 1.5 to 2.5 at row y = j - 0.5
    for (uint32_t i = 0; i < f.samples_x(); ++i) {
      const size_t k = f.sample_index(i, j);
      const double x = double(i) - 0.5;
      f.distance[k] = float(std::abs(x - 1.7));
      f.gradient[2 * k] = x < 1.7 ? -1.0f : 1.0f;
      // The line runs down (+y): side +1 (cross >= 0) is on its left on screen, x < 1.7.
      f.side[k] = x < 1.7 ? 1 : -1;
    }
  }
  for (uint32_t j = 0; j < f.cells_y(); ++j) f.segments[f.cell_index(2, j)] = 1u << 4;  // P0 - P2
  return f;
}

// Makes cell (i, j) a junction at cell-local (u, v) with the given junction_spokes byte (the fixture's only one).
inline void add_crease_junction(CreaseField& f, uint32_t i, uint32_t j, float u, float v, uint8_t spokes) {
  f.segments[f.cell_index(i, j)] = kCreaseJunctionBit;
  f.junction_cells = {uint32_t(f.cell_index(i, j))};
  f.junction_points = {u, v};
  f.junction_spokes = {spokes};
}

inline std::vector<uint8_t> crease_bytes(const std::function<void(CreaseField&)>& corrupt = {},
                                         const nlohmann::json& parameters = {{"width", 3}, {"height", 2}}) {
  CreaseField f = valid_crease_field();
  if (corrupt) corrupt(f);
  nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                         {"parameters", parameters},
                         {"conventions", {{"normal_convention", "+Y"}}},
                         {"statistics", nlohmann::json::object()}};
  AssetWriter w("crease", meta);
  add_crease_sections(w, std::move(f));
  return w.serialize();
}

}  // namespace mbk::test
