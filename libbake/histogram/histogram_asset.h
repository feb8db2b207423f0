// The `histogram` asset kind (formats/kind_histogram.cpp, formats/SPEC.md "Kind 11: histogram"): a baked exact
// histogram (histogram_bake.h) as a file.
#pragma once

#include "formats/asset_writer.h"
#include "libbake/histogram/histogram_bake.h"

namespace mbk {

// Sections `theta_edges` f64 [K + 1], `theta_centres` f64 [K], `phi_edges` f64 [N + 1], `bin_counts` u32
// [H + 1, W + 1, K N]. Metadata parameters {width, height, method "exact", theta_bins (K), theta_bins_requested,
// phi_bins (N), seed}; statistics {theta_edges_degrees, distinct_theta_values, lloyd_iterations, theta_rms_error,
// empty_bins, table_bytes}. Takes the table over (no copy).
AssetWriter histogram_asset_writer(const LoadedNormalMap& input, const HistogramBakeOptions& options, uint64_t seed,
                                   BakedHistogram&& baked);

}  // namespace mbk
