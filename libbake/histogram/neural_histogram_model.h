// The neural histogram's model ([Shah24] Sec. 4.2, Eq. 11; layout in formats/neural_histogram_layout.h): a feature
// pyramid looked up trilinearly by a footprint's centre (wrapping around the map) and log2 size, as NeuMIP [KMX*21]
// does, and K + 1 MLPs decoding the interpolated features (plus the footprint's log size) into P(theta_j) and
// P(phi_i | theta_j), whose products are the probabilities of the K x N bins. The same code serves training (f32
// values) and reading (the asset's f16 values, widened), so that what is measured is what the file predicts.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "formats/neural_histogram_layout.h"

namespace mbk {

// A pyramid of textures over a W x H map, looked up trilinearly ([Wil83], as NeuMIP [KMX*21]): level l is
// level_width[l] x level_height[l] texels (stored level after level from level_offset[l]); level 0's texels are
// about `base` map texels wide, and each level doubles them.
struct PyramidGrid {
  uint32_t width = 0, height = 0;
  double base = 1.0;
  std::vector<uint32_t> level_width, level_height;
  std::vector<uint64_t> level_offset;
  uint32_t levels() const { return uint32_t(level_width.size()); }
};
// The neural histogram's pyramid (formats/neural_histogram_layout.h), base 8.
PyramidGrid neural_pyramid_grid(const NeuralHistogramShape& shape);

// The 8 pyramid texels a footprint reads (4 bilinear corners on each of two levels) and their weights, which sum
// to 1.
struct PyramidLookup {
  std::array<uint64_t, 8> texel{};  // indices into the pyramid (its texels level after level)
  std::array<float, 8> weight{};
};

// Footprint centre (x, y) in texels of the map (wrapping), side in texels. The level is lod = log2(side / base)
// clamped to [0, L - 1], blended between floor(lod) and the next level; on level l the centre is at
// (x w_l / W - 1/2, y h_l / H - 1/2) in texel units, bilinear between the four texels around it (wrapping).
PyramidLookup pyramid_lookup(const PyramidGrid& grid, double x, double y, double side);

struct NeuralHistogramModel {
  NeuralHistogramModel() = default;
  // A model of `shape` with every feature and parameter 0.
  explicit NeuralHistogramModel(const NeuralHistogramShape& shape);

  NeuralHistogramShape shape;
  PyramidGrid grid;
  std::vector<float> features;  // [P, F]
  std::vector<float> mlp;       // [M]

  // The network input of a footprint of `side` texels whose lookup is `lookup`: the F interpolated features, then
  // log2(side / 8) / 8 (F + 1 floats at `input`).
  void network_input(const PyramidLookup& lookup, double side, float* input) const;
  // P(bin) of every bin (K N values, bin j N + i) for a footprint of side >= 8 texels centred at (x, y).
  void probabilities(double x, double y, double side, std::span<double> out) const;
  // Every feature and parameter rounded to f16 (what the asset stores), in place.
  void round_to_half();
};

}  // namespace mbk
