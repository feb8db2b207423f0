// Baking asset kind `colormap` ([Heitz13] Sec. 4.2, Eq. 10; formats/SPEC.md "Kind 7: colormap"): the colour map C
// convolved with N(0, sigma^2) for sigma in [0, sigma_max], tabulated over (mean, sigma), so that a shader gets
// the filtered colour of a driver with Gaussian statistics over the pixel footprint, E[C(f)] with
// f ~ N(mean, sigma^2), from one bilinear lookup. The table is the closed form of formats/colormap_layout.h
// (exact for the piecewise-linear C), evaluated in double and stored as float.
#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>

#include "formats/asset_writer.h"
#include "formats/colormap_layout.h"
#include "libbake/core/progress.h"

namespace mbk {

struct ColormapTableOptions {
  uint32_t width = kColormapDefaultSide;   // mean samples
  uint32_t height = kColormapDefaultSide;  // sigma samples
  double mean_min = 0.0, mean_max = 1.0;
  // 0 means the default: (mean_max - mean_min) / 2, the largest standard deviation a driver bounded to
  // [mean_min, mean_max] can have (half its values at each end).
  double sigma_max = 0.0;
};

// What the sampling costs, in linear colour units (max over the channels).
struct ColormapTableStatistics {
  // |bilinear lookup - exact convolution| at the centre of every table cell (between four entries), where
  // the interpolation error is largest: the error of the table size.
  double lookup_max_error = 0.0, lookup_rms_error = 0.0;
  // max |[C * N(0, sigma^2)](m) - C(m)| over the entries: how far the naive C(mean f) is from the filtered
  // colour for this map, at worst over the table.
  double naive_max_error = 0.0;
  nlohmann::json to_json() const;
};

struct BakedColormap {
  ColormapCurve curve;  // C as stored (knots and colours rounded to float, the values the table is computed from)
  ColormapTable table;
  ColormapTableStatistics statistics;
};

// Error(bad_command_line) for sizes outside 2..8192, a negative or non-finite sigma_max or an empty mean range;
// Error(invalid_input) for an invalid curve. Deterministic whatever the thread count.
BakedColormap bake_colormap_table(const ColormapCurve& curve, const ColormapTableOptions& options, Progress& progress);

// The asset: sections and metadata of formats/SPEC.md "Kind 7: colormap"; `input` is the source's record and
// `encoding` the transfer applied to it ("srgb" or "linear").
AssetWriter colormap_asset_writer(const BakedColormap& baked, const nlohmann::json& input, const std::string& encoding);

}  // namespace mbk
