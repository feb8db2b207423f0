// The exact binned P-NDF of any footprint in O(bins) ([GGN18]; [Shah24] Sec. 4.2's "summed area table"): one
// integral image of counts per bin over the whole map, in the layout of formats/histogram_layout.h (each corner's
// counts of all bins contiguous, so a footprint reads at most 16 runs of `bins` values). Built in two passes, each
// parallel and exact in integers: per-row running counts (rows independent), then the sum down the columns (rows in
// order, each row's entries split among the threads), so the table is the same whatever the thread count.
#pragma once

#include <cstdint>

#include "formats/histogram_layout.h"
#include "libbake/core/progress.h"
#include "libbake/core/uninitialized_vector.h"
#include "libbake/image/normal_map.h"

namespace mbk {

// The bin of every texel of `map`, row-major.
std::vector<uint32_t> texel_bins(const NormalMap& map, const HistogramBins& bins);

// The table of a map whose texels are in bins `texel_bin` (row-major, W x H, each < bins):
// [H + 1, W + 1, bins] u32 counts.
UninitializedVector<uint32_t> bin_count_table(const std::vector<uint32_t>& texel_bin, uint32_t width, uint32_t height,
                                              uint32_t bins, Progress& progress);

}  // namespace mbk
