// The MIP pyramid of histograms (see histogram_pyramid_baseline.h).
#include "libbake/histogram/histogram_pyramid_baseline.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>

namespace mbk {
namespace {

// The pyramid whose level 0 has n cells across the map's longer side.
PyramidGrid baseline_grid(uint32_t width, uint32_t height, uint32_t n) {
  PyramidGrid grid;
  grid.width = width;
  grid.height = height;
  const uint32_t longer = std::max(width, height);
  grid.base = double(longer) / n;
  uint32_t w = std::max<uint32_t>(1, uint32_t(std::lround(double(n) * width / longer)));
  uint32_t h = std::max<uint32_t>(1, uint32_t(std::lround(double(n) * height / longer)));
  uint64_t offset = 0;
  for (;;) {
    grid.level_width.push_back(w);
    grid.level_height.push_back(h);
    grid.level_offset.push_back(offset);
    offset += uint64_t(w) * h;
    if (w == 1 && h == 1) break;
    w = (w + 1) / 2;
    h = (h + 1) / 2;
  }
  grid.level_offset.push_back(offset);  // the total, read below
  return grid;
}

uint64_t grid_texels(const PyramidGrid& grid) { return grid.level_offset.back(); }

}  // namespace

uint64_t neural_predictor_bytes(const NeuralHistogramShape& shape) {
  return (shape.pyramid_texels() * shape.features + shape.mlp_parameters()) * 2;
}

HistogramPyramidBaseline::HistogramPyramidBaseline(HistogramAssetView view, uint64_t bytes)
    : exact_(std::move(view)), bins_(exact_.bins().count()) {
  const BinCountTable& table = exact_.view().table;
  const uint64_t per_texel = uint64_t(bins_) * 2;
  uint32_t n = 1;
  while (n < std::max(table.width, table.height) &&
         grid_texels(baseline_grid(table.width, table.height, n + 1)) * per_texel <= bytes)
    ++n;
  grid_ = baseline_grid(table.width, table.height, n);
  const uint64_t texels = grid_texels(grid_);
  grid_.level_offset.pop_back();
  histograms_.resize(texels * bins_);
  std::vector<uint64_t> counts(bins_);
  for (uint32_t l = 0; l < grid_.levels(); ++l) {
    const uint32_t w = grid_.level_width[l], h = grid_.level_height[l];
    for (uint32_t r = 0; r < h; ++r)
      for (uint32_t c = 0; c < w; ++c) {
        // The cell's whole texels: [x0, x1) x [y0, y1), at least one texel.
        const int64_t x0 = std::llround(double(c) * table.width / w), y0 = std::llround(double(r) * table.height / h);
        const int64_t x1 = std::max<int64_t>(x0 + 1, std::llround(double(c + 1) * table.width / w));
        const int64_t y1 = std::max<int64_t>(y0 + 1, std::llround(double(r + 1) * table.height / h));
        footprint_histogram(table, x0, y0, uint64_t(x1 - x0), uint64_t(y1 - y0), counts);
        float* out = histograms_.data() + (grid_.level_offset[l] + uint64_t(r) * w + c) * bins_;
        const double area = double(x1 - x0) * double(y1 - y0);
        for (uint32_t b = 0; b < bins_; ++b) out[b] = float(Imath::half(float(double(counts[b]) / area)));
      }
  }
}

void HistogramPyramidBaseline::footprint_probabilities(const SquareFootprint& f, std::span<double> out) const {
  const FootprintTexels t = square_footprint_texels(f);
  if (t.w < kNeuralHistogramMinFootprint) {
    exact_.footprint_probabilities(f, out);
    return;
  }
  const PyramidLookup lookup = pyramid_lookup(grid_, f.x, f.y, double(t.w));
  std::fill(out.begin(), out.end(), 0.0);
  double sum = 0.0;
  for (int k = 0; k < 8; ++k) {
    const float* h = histograms_.data() + lookup.texel[k] * bins_;
    for (uint32_t b = 0; b < bins_; ++b) out[b] += double(lookup.weight[k]) * h[b];
  }
  for (double v : out) sum += v;
  for (double& v : out) v /= sum;  // f16 rounding leaves the sum within 2^-11 of 1
}

}  // namespace mbk
