// Integral images of per-bin counts (see bin_count_table.h).
#include "libbake/histogram/bin_count_table.h"

#include <algorithm>

#include "libbake/core/parallel.h"

namespace mbk {

// Every count is at most W x H, which the side limit keeps within 32 bits.
static_assert(kHistogramMaxSide == kMaxNormalMapSide && uint64_t(kMaxNormalMapSide) * kMaxNormalMapSide <= UINT32_MAX);

std::vector<uint32_t> texel_bins(const NormalMap& map, const HistogramBins& bins) {
  std::vector<uint32_t> out(size_t(map.width) * map.height);
  parallel_for(0, map.height, [&](int64_t row) {
    for (uint32_t x = 0; x < map.width; ++x) {
      const size_t t = size_t(row) * map.width + x;
      const Vec3f& n = map.texels[t];
      out[t] = bins.bin_of(n.x(), n.y(), n.z());
    }
  });
  return out;
}

UninitializedVector<uint32_t> bin_count_table(const std::vector<uint32_t>& texel_bin, uint32_t width, uint32_t height,
                                              uint32_t bins, Progress& progress) {
  const size_t row_entries = (size_t(width) + 1) * bins;
  UninitializedVector<uint32_t> table(histogram_table_entries(width, height, bins));
  progress.start("histogram table", uint64_t(height) * 2);
  // Pass 1: table row Y + 1 holds the running counts along image row Y; table row 0 is zero.
  parallel_for(0, int64_t(height) + 1, [&](int64_t y) {
    uint32_t* out = table.data() + size_t(y) * row_entries;
    std::fill(out, out + bins, 0u);
    if (y == 0) {
      std::fill(out, out + row_entries, 0u);
      return;
    }
    const uint32_t* row_bins = texel_bin.data() + size_t(y - 1) * width;
    for (uint32_t x = 0; x < width; ++x) {
      uint32_t* cell = out + size_t(x + 1) * bins;
      std::copy(cell - bins, cell, cell);
      ++cell[row_bins[x]];
    }
    progress.advance();
  });
  // Pass 2: add each table row to the next, down the columns; a thread owns a slice of every row.
  constexpr size_t kSlice = 1 << 14;
  const int64_t slices = int64_t((row_entries + kSlice - 1) / kSlice);
  parallel_for(0, slices, [&](int64_t s) {
    const size_t begin = size_t(s) * kSlice, end = std::min(row_entries, begin + kSlice);
    for (uint32_t y = 2; y <= height; ++y) {
      const uint32_t* above = table.data() + size_t(y - 1) * row_entries;
      uint32_t* here = table.data() + size_t(y) * row_entries;
      for (size_t i = begin; i < end; ++i) here[i] += above[i];
    }
  });
  progress.advance(height);
  progress.finish();
  return table;
}

}  // namespace mbk
