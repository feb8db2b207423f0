// Where the histogram effect gets a footprint's binned P-NDF ([Shah24] Eq. 3's normalised counts c_j / N_P): one
// interface, two sources. The exact one reads a `histogram` asset's integral images (formats/histogram_layout.h,
// [GGN18]); a compressed one (the neural histogram of [Shah24] Sec. 4.2) predicts the same probabilities. The
// renderer asks for the bins and their centres once and then for the probabilities of many square footprints.
//
// Footprints are squares on the map repeated in both directions, in texels of the finest map: centre (x, y) with x
// to the right and y down from the top-left corner (texel (i, row) covers [i, i + 1) x [row, row + 1)), side >= 1
// (smaller sides, and NaN, are taken as 1; sides above 2^24, +inf included, as 2^24). The centre must be finite. The
// exact source covers the whole texels of the w x w square with w = max(1, round(side)) whose top-left texel is
// (floor(x - w / 2 + 1/2), floor(y - w / 2 + 1/2)), equal weights
// ([Shah24] Eq. 2).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "formats/histogram_layout.h"

namespace mbk {

struct SquareFootprint {
  double x = 0, y = 0;  // centre, texels
  double side = 1;      // texels
};

// The whole-texel square an exact source counts: top-left texel (x0, row0), w texels a side.
struct FootprintTexels {
  int64_t x0 = 0, row0 = 0;
  uint64_t w = 1;
};
FootprintTexels square_footprint_texels(const SquareFootprint& f);

// A square that covers a W x H map a whole number of times in both directions (side lcm(W, H)), whose
// probabilities are the whole map's histogram (up to the 2^24 clamp of sides, for maps whose lcm is above it).
SquareFootprint whole_map_footprint(uint32_t width, uint32_t height);

class BinnedNdfSource {
 public:
  virtual ~BinnedNdfSource() = default;
  virtual const HistogramBins& bins() const = 0;
  // The K theta-bin centres (radians); the phi centre of bin i is 2 pi (i + 1/2) / N.
  virtual std::span<const double> theta_centres() const = 0;
  virtual uint32_t width() const = 0;
  virtual uint32_t height() const = 0;
  // P(bin) for every bin (bins().count() values, >= 0, summing to 1) over the footprint.
  virtual void footprint_probabilities(const SquareFootprint& f, std::span<double> out) const = 0;
};

// The exact source over a `histogram` asset's view (which must outlive it).
class ExactBinnedNdf : public BinnedNdfSource {
 public:
  explicit ExactBinnedNdf(HistogramAssetView view) : view_(std::move(view)) {}
  const HistogramAssetView& view() const { return view_; }
  const HistogramBins& bins() const override { return view_.bins; }
  std::span<const double> theta_centres() const override { return view_.theta_centres; }
  uint32_t width() const override { return view_.table.width; }
  uint32_t height() const override { return view_.table.height; }
  void footprint_probabilities(const SquareFootprint& f, std::span<double> out) const override;

 private:
  HistogramAssetView view_;
};

}  // namespace mbk
