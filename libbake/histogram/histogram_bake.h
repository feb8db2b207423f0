// `microbake histogram --method exact`: a normal map's adaptive bins (adaptive_theta_bins.h, [Shah24] Sec. 4.1) and
// the integral images of its per-bin counts (bin_count_table.h, [GGN18]), from which formats/histogram_layout.h reads
// the exact binned P-NDF (Eq. 3's counts) of any footprint.
#pragma once

#include <cstdint>
#include <string>

#include "formats/histogram_layout.h"
#include "libbake/core/progress.h"
#include "libbake/core/uninitialized_vector.h"
#include "libbake/histogram/adaptive_theta_bins.h"
#include "libbake/image/normal_map.h"

namespace mbk {

enum class ThetaBinning { adaptive, uniform };  // adaptive_theta_bins or uniform_theta_bins

struct HistogramBakeOptions {
  uint32_t theta_bins = kHistogramDefaultThetaBins;  // requested; fewer when the map has fewer distinct thetas
  uint32_t phi_bins = kHistogramDefaultPhiBins;
  ThetaBinning theta_binning = ThetaBinning::adaptive;
};

// "adaptive" or "uniform", as metadata and options spell it.
const char* theta_binning_name(ThetaBinning binning);

struct BakedHistogram {
  uint32_t width = 0, height = 0;
  ThetaBins theta;
  HistogramBins bins;
  UninitializedVector<uint32_t> counts;  // [H + 1, W + 1, bins]
  BinCountTable table() const { return {width, height, bins.count(), counts}; }
};

// Error(invalid_input) naming the bytes when a W x H map's table at the requested bins would exceed
// kHistogramMaxTableBytes (the requested bins, not the ones a map may end with, so the answer depends on the
// command line and the map's size alone).
void check_histogram_table_size(uint32_t width, uint32_t height, const HistogramBakeOptions& options,
                                const std::string& where);

// The k-means seed of an input: the 64 bits of its content hash ("xxh3:<16 hex>", InputRecord::content_hash).
uint64_t histogram_seed(const std::string& content_hash);

// Bakes a map of unit normals with z >= 0 (as load_normal_map gives them; Error(invalid_input) for any other
// texel). Checks the size first.
BakedHistogram bake_histogram(const NormalMap& map, const HistogramBakeOptions& options, uint64_t seed,
                              Progress& progress, const std::string& where);

}  // namespace mbk
