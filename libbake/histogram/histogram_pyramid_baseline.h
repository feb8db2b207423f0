// The non-neural compressed binned P-NDF the neural histogram is measured against (issue 13 part 3; in memory only,
// for scripts/bench-neural-histogram.sh): a MIP pyramid of footprint histograms with trilinear interpolation, as
// Deng et al. 2022 ([DLW*22]) reconstruct a footprint's NDF, of a given byte budget. Level 0 holds the exact
// normalised histograms of an n x m grid of cells over the map (n as large as the budget allows at 2 bytes per
// bin, f16 as the neural histogram stores its values), each coarser level the histograms of cells twice as wide; a
// footprint blends the 4 cells around its centre on the two levels around log2(side / cell), as
// neural_histogram_model.h looks its features up.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "formats/histogram_layout.h"
#include "libbake/histogram/neural_histogram_model.h"

namespace mbk {

class HistogramPyramidBaseline {
 public:
  // The densest such pyramid over the map of `table` whose histograms take at most `bytes` (at least 1 x 1).
  HistogramPyramidBaseline(const BinCountTable& table, uint64_t bytes);
  uint64_t bytes() const { return uint64_t(histograms_.size()) * 2; }
  const PyramidGrid& grid() const { return grid_; }
  // P(bin) of a footprint of `side` texels centred at (x, y).
  void probabilities(double x, double y, double side, std::span<double> out) const;

 private:
  PyramidGrid grid_;
  uint32_t bins_ = 0;
  std::vector<float> histograms_;  // [texels of all levels, bins], f16 values
};

}  // namespace mbk
