// The neural histogram as a BinnedNdfSource (binned_ndf_source.h): footprints of 8 x 8 texels or more are predicted
// by the model ([Shah24] Sec. 4.2, Eq. 11; neural_histogram_model.h), smaller ones are counted exactly from every
// texel's stored bin ("we can explicitly iterate over all the corresponding normals for smaller footprints").
#pragma once

#include <memory>
#include <vector>

#include "libbake/histogram/binned_ndf_source.h"
#include "libbake/histogram/neural_histogram_model.h"

namespace mbk {

class Asset;

class NeuralBinnedNdf : public BinnedNdfSource {
 public:
  NeuralBinnedNdf(NeuralHistogramModel model, HistogramBins bins, std::vector<double> theta_centres,
                  std::vector<uint16_t> texel_bins);
  const HistogramBins& bins() const override { return bins_; }
  std::span<const double> theta_centres() const override { return theta_centres_; }
  uint32_t width() const override { return model_.shape.width; }
  uint32_t height() const override { return model_.shape.height; }
  void footprint_probabilities(const SquareFootprint& f, std::span<double> out) const override;

 private:
  NeuralHistogramModel model_;
  HistogramBins bins_;
  std::vector<double> theta_centres_;
  std::vector<uint16_t> texel_bins_;  // [H, W]
};

// The source of a `neural_histogram` asset (opened by Asset::open/parse, so checked); independent of the asset
// afterwards (it holds the f16 values widened to f32).
std::unique_ptr<BinnedNdfSource> open_neural_histogram(const Asset& asset);

}  // namespace mbk
