// Square footprints in whole texels, and the exact source's probabilities (binned_ndf_source.h).
#include "libbake/histogram/binned_ndf_source.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mbk {

FootprintTexels square_footprint_texels(const SquareFootprint& f) {
  FootprintTexels t;
  // NaN is taken as one texel; +inf (a grazing footprint) as the largest side, i.e. the whole map many times over.
  const double side = std::isnan(f.side) ? 1.0 : std::max(1.0, f.side);
  // Sides above 2^24 texels (1024 times the largest map's) are clamped, so that w^2 stays far inside 64 bits; such a
  // footprint's probabilities then differ from the unclamped ones by less than 16384 / 2^24 = 0.001.
  t.w = uint64_t(std::llround(std::min(side, 0x1p24)));
  const double half = 0.5 * double(t.w);
  t.x0 = int64_t(std::floor(f.x - half + 0.5));
  t.row0 = int64_t(std::floor(f.y - half + 0.5));
  return t;
}

SquareFootprint whole_map_footprint(uint32_t width, uint32_t height) {
  SquareFootprint f;
  f.side = double(std::lcm(uint64_t(width), uint64_t(height)));
  f.x = f.y = 0.5 * f.side;
  return f;
}

void ExactBinnedNdf::footprint_probabilities(const SquareFootprint& f, std::span<double> out) const {
  const FootprintTexels t = square_footprint_texels(f);
  const uint32_t bins = view_.bins.count();
  std::vector<uint64_t> counts(bins);
  footprint_histogram(view_.table, t.x0, t.row0, t.w, t.w, counts);
  const double area = double(t.w) * double(t.w);
  for (uint32_t b = 0; b < bins; ++b) out[b] = double(counts[b]) / area;
}

}  // namespace mbk
