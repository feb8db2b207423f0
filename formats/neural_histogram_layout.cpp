// Sizes and reader view of the `neural_histogram` asset (see neural_histogram_layout.h).
#include "formats/neural_histogram_layout.h"

#include <algorithm>

#include "formats/asset.h"

namespace mbk {

uint32_t NeuralHistogramShape::level_width(uint32_t level) const {
  uint32_t w = (width + kNeuralHistogramMinFootprint - 1) / kNeuralHistogramMinFootprint;
  for (uint32_t l = 0; l < level; ++l) w = (w + 1) / 2;
  return w;
}

uint32_t NeuralHistogramShape::level_height(uint32_t level) const {
  uint32_t h = (height + kNeuralHistogramMinFootprint - 1) / kNeuralHistogramMinFootprint;
  for (uint32_t l = 0; l < level; ++l) h = (h + 1) / 2;
  return h;
}

uint32_t NeuralHistogramShape::levels() const {
  uint32_t l = 0;
  while (level_width(l) > 1 || level_height(l) > 1) ++l;
  return l + 1;
}

uint64_t NeuralHistogramShape::level_offset(uint32_t level) const {
  uint64_t offset = 0;
  for (uint32_t l = 0; l < level; ++l) offset += uint64_t(level_width(l)) * level_height(l);
  return offset;
}

uint64_t NeuralHistogramShape::pyramid_texels() const { return level_offset(levels()); }

uint64_t NeuralHistogramShape::network_offset(uint32_t m) const {
  // Network 0 (theta) first, then the K phi networks, all of one size.
  return m == 0 ? 0 : network(0).parameters() + uint64_t(m - 1) * network(1).parameters();
}

uint64_t NeuralHistogramShape::mlp_parameters() const { return network_offset(networks()); }

uint64_t NeuralHistogramShape::model_bytes() const {
  return uint64_t(width) * height * 2 + pyramid_texels() * features * 2 + mlp_parameters() * 2;
}

namespace {

std::span<const uint16_t> u16_section(const Asset& asset, const char* name) {
  const std::span<const uint8_t> bytes = asset.bytes_of(asset.section(name));
  return {reinterpret_cast<const uint16_t*>(bytes.data()), bytes.size() / sizeof(uint16_t)};
}

}  // namespace

NeuralHistogramAssetView neural_histogram_asset_view(const Asset& asset) {
  const nlohmann::json& p = asset.metadata()["parameters"];
  NeuralHistogramAssetView view;
  view.shape = {p["width"].get<uint32_t>(),    p["height"].get<uint32_t>(),   p["theta_bins"].get<uint32_t>(),
                p["phi_bins"].get<uint32_t>(), p["features"].get<uint32_t>(), p["hidden"].get<uint32_t>()};
  view.bins = {asset.read<double>(kHistogramThetaEdgesSection), view.shape.phi_bins};
  view.theta_centres = asset.read<double>(kHistogramThetaCentresSection);
  view.texel_bins = u16_section(asset, kNeuralHistogramTexelBinsSection);
  view.features = u16_section(asset, kNeuralHistogramFeaturesSection);
  view.mlp = u16_section(asset, kNeuralHistogramMlpSection);
  return view;
}

}  // namespace mbk
