// The non-neural compressed binned P-NDF the neural histogram is measured against (issue 13 part 3): a MIP pyramid
// of footprint histograms with trilinear interpolation, as Deng et al. 2022 ([DLW*22]) reconstruct a footprint's
// NDF, of a given byte budget, built in memory from the exact table (the `histogram` effect's `method pyramid`, and
// tests/bench/neural_histogram_bench.cpp). Level 0 holds the exact normalised histograms of an n x m grid of cells
// over the map (n as large as the budget allows at 2 bytes per bin, f16 as the neural histogram stores its values),
// each coarser level the histograms of cells twice as wide; a footprint blends the 4 cells around its centre on the
// two levels around log2(side / cell), as neural_histogram_model.h looks its features up. Footprints below
// kNeuralHistogramMinFootprint texels a side are counted exactly, as the neural histogram counts them from its
// stored texel bins, so that the two differ only where one predicts and the other interpolates.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "formats/histogram_layout.h"
#include "formats/neural_histogram_layout.h"
#include "libbake/histogram/binned_ndf_source.h"
#include "libbake/histogram/neural_histogram_model.h"

namespace mbk {

// The bytes of a neural histogram's predictor (its feature pyramid and networks, f16): the budget of the baseline
// "of equal bytes" (the stored texel bins, which both use for small footprints, are left out of both).
uint64_t neural_predictor_bytes(const NeuralHistogramShape& shape);

class HistogramPyramidBaseline : public BinnedNdfSource {
 public:
  // The densest such pyramid over the exact table of `view` (which must outlive it) whose histograms take at most
  // `bytes` (at least 1 x 1).
  HistogramPyramidBaseline(HistogramAssetView view, uint64_t bytes);
  uint64_t bytes() const { return uint64_t(histograms_.size()) * 2; }
  const PyramidGrid& grid() const { return grid_; }

  const HistogramBins& bins() const override { return exact_.bins(); }
  std::span<const double> theta_centres() const override { return exact_.theta_centres(); }
  uint32_t width() const override { return exact_.width(); }
  uint32_t height() const override { return exact_.height(); }
  void footprint_probabilities(const SquareFootprint& f, std::span<double> out) const override;

 private:
  ExactBinnedNdf exact_;
  PyramidGrid grid_;
  uint32_t bins_ = 0;
  std::vector<float> histograms_;  // [texels of all levels, bins], f16 values
};

}  // namespace mbk
