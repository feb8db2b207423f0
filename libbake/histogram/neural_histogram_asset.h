// The `neural_histogram` asset kind (formats/kind_neural_histogram.cpp, formats/SPEC.md "Kind 12:
// neural_histogram"): a baked neural histogram (neural_histogram_bake.h) as a file.
#pragma once

#include <string>

#include "formats/asset_writer.h"
#include "libbake/histogram/neural_histogram_bake.h"

namespace mbk {

// Sections `theta_edges` f64 [K + 1], `theta_centres` f64 [K], `texel_bins` u16 [H, W], `features` f16 [P, F],
// `mlp` f16 [M]. Metadata parameters {width, height, method "neural", theta_bins, theta_bins_requested, phi_bins,
// theta_binning, seed (k-means), features, hidden, levels, min_footprint, iterations, batch, training_seed (--seed)};
// statistics {theta_edges_degrees, distinct_theta_values, lloyd_iterations, theta_rms_error, training_loss,
// held_out_kl, marginal_kl, exact_table_bytes}.
AssetWriter neural_histogram_asset_writer(const LoadedNormalMap& input, const NeuralHistogramBakeOptions& options,
                                          uint64_t kmeans_seed, BakedNeuralHistogram&& baked);

// Bakes `input`'s map (k-means seed from its content hash) and returns its asset.
AssetWriter bake_neural_histogram_asset(const LoadedNormalMap& input, const NeuralHistogramBakeOptions& options,
                                        Progress& progress, const std::string& where);

}  // namespace mbk
