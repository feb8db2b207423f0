// The `neural_histogram` asset's layout (formats/kind_neural_histogram.cpp, formats/SPEC.md "Kind 12:
// neural_histogram"): [Shah24] Sec. 4.2's neural histogram, i.e. a feature pyramid (NeuMIP-like, [KMX*21]) and
// K + 1 small MLPs (Eq. 11: one for P(theta_j), one per theta bin for P(phi_i | theta_j)), with the adaptive bins of
// formats/histogram_layout.h and, for footprints below 8 x 8 texels, every texel's bin. Shared by the baker
// (libbake/histogram/neural_histogram_bake.h), the reader (libbake/histogram/neural_binned_ndf.h) and the validator,
// so that all three derive the same section sizes from the parameters.
//
// Pyramid: level 0 is ceil(W / 8) x ceil(H / 8) texels, level l + 1 is ceil(w_l / 2) x ceil(h_l / 2), down to
// 1 x 1 (L levels). `features` f16 [P, F] holds the levels in order, each row-major (row 0 at the top), P the sum
// of their texels.
//
// MLPs: network 0 predicts the K theta logits, network 1 + j the N phi logits of theta bin j. Each is
// in -> hidden -> hidden -> out with ReLU after both hidden layers, in = F + 1 (the interpolated features and the
// footprint's log2(side / 8) / 8). `mlp` f16 [M] holds the networks in order, each as W1 [hidden, in], b1 [hidden],
// W2 [hidden, hidden], b2 [hidden], W3 [out, hidden], b3 [out], matrices row-major.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "formats/histogram_layout.h"

namespace mbk {

inline constexpr uint32_t kNeuralHistogramKindId = 12;
inline constexpr uint32_t kNeuralHistogramMinFootprint = 8;  // [Shah24] Sec. 4.2: smaller footprints are counted
inline constexpr uint32_t kNeuralHistogramHidden = 64;       // the paper's 64 x 2
inline constexpr uint32_t kNeuralHistogramMaxHidden = 1024;
inline constexpr uint32_t kNeuralHistogramDefaultFeatures = 16;
inline constexpr uint32_t kNeuralHistogramMaxFeatures = 256;

inline constexpr const char* kNeuralHistogramTexelBinsSection = "texel_bins";
inline constexpr const char* kNeuralHistogramFeaturesSection = "features";
inline constexpr const char* kNeuralHistogramMlpSection = "mlp";

// One MLP's sizes and the offsets of its parameters within its block of `mlp`.
struct MlpShape {
  uint32_t in = 0, hidden = 0, out = 0;
  uint64_t w1() const { return 0; }
  uint64_t b1() const { return w1() + uint64_t(hidden) * in; }
  uint64_t w2() const { return b1() + hidden; }
  uint64_t b2() const { return w2() + uint64_t(hidden) * hidden; }
  uint64_t w3() const { return b2() + hidden; }
  uint64_t b3() const { return w3() + uint64_t(out) * hidden; }
  uint64_t parameters() const { return b3() + out; }
};

// Everything the sections' sizes follow from.
struct NeuralHistogramShape {
  uint32_t width = 0, height = 0;
  uint32_t theta_bins = 0, phi_bins = 0;  // K, N
  uint32_t features = 0, hidden = 0;      // F, hidden width

  uint32_t levels() const;
  uint32_t level_width(uint32_t level) const;
  uint32_t level_height(uint32_t level) const;
  uint64_t level_offset(uint32_t level) const;  // first texel of the level in `features`
  uint64_t pyramid_texels() const;              // P
  uint32_t inputs() const { return features + 1; }
  uint32_t networks() const { return theta_bins + 1; }
  MlpShape network(uint32_t m) const { return {inputs(), hidden, m == 0 ? theta_bins : phi_bins}; }
  uint64_t network_offset(uint32_t m) const;  // first parameter of network m in `mlp`
  uint64_t mlp_parameters() const;            // M
  // Bytes of the three big sections (texel bins, features, MLPs), the asset's size but for its bins and metadata.
  uint64_t model_bytes() const;
};

class Asset;

// A `neural_histogram` asset as a reader uses it: shape, bins and views of its sections (into the asset's bytes,
// valid while the asset lives). The asset must have passed its kind's checks (Asset::open/parse run them).
struct NeuralHistogramAssetView {
  NeuralHistogramShape shape;
  HistogramBins bins;
  std::vector<double> theta_centres;
  std::span<const uint16_t> texel_bins;  // [H, W]
  std::span<const uint16_t> features;    // f16 bits, [P, F]
  std::span<const uint16_t> mlp;         // f16 bits, [M]
};
NeuralHistogramAssetView neural_histogram_asset_view(const Asset& asset);

}  // namespace mbk
