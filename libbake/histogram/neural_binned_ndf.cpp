// Footprint probabilities of the neural histogram, and opening its asset (see neural_binned_ndf.h).
#include "libbake/histogram/neural_binned_ndf.h"

#include <Imath/half.h>

#include <algorithm>

#include "formats/asset.h"

namespace mbk {

NeuralBinnedNdf::NeuralBinnedNdf(NeuralHistogramModel model, HistogramBins bins, std::vector<double> theta_centres,
                                 std::vector<uint16_t> texel_bins)
    : model_(std::move(model)),
      bins_(std::move(bins)),
      theta_centres_(std::move(theta_centres)),
      texel_bins_(std::move(texel_bins)) {}

void NeuralBinnedNdf::footprint_probabilities(const SquareFootprint& f, std::span<double> out) const {
  const FootprintTexels t = square_footprint_texels(f);
  if (t.w >= kNeuralHistogramMinFootprint) {
    model_.probabilities(f.x, f.y, double(t.w), out);
    return;
  }
  const int64_t W = width(), H = height();
  std::fill(out.begin(), out.end(), 0.0);
  const double texel = 1.0 / double(t.w * t.w);
  for (int64_t r = 0; r < int64_t(t.w); ++r) {
    const int64_t row = ((t.row0 + r) % H + H) % H;
    for (int64_t c = 0; c < int64_t(t.w); ++c) {
      const int64_t column = ((t.x0 + c) % W + W) % W;
      out[texel_bins_[size_t(row * W + column)]] += texel;
    }
  }
}

std::unique_ptr<BinnedNdfSource> open_neural_histogram(const Asset& asset) {
  const NeuralHistogramAssetView view = neural_histogram_asset_view(asset);
  NeuralHistogramModel model(view.shape);
  auto widen = [](std::span<const uint16_t> bits) {
    std::vector<float> values(bits.size());
    for (size_t i = 0; i < bits.size(); ++i) {
      Imath::half h;
      h.setBits(bits[i]);
      values[i] = float(h);
    }
    return values;
  };
  model.features = widen(view.features);
  model.mlp = widen(view.mlp);
  return std::make_unique<NeuralBinnedNdf>(std::move(model), view.bins, view.theta_centres,
                                           std::vector<uint16_t>(view.texel_bins.begin(), view.texel_bins.end()));
}

}  // namespace mbk
