// Baking asset kind `lut` (formats/SPEC.md "Kind 2: lut"; formats/lut_layout.h): the standardization tables of
// an example normal map for histogram-preserving blending ([Wang20] Eq. 6, [Heitz18] Sec. 3), per channel n_x
// and n_y, with the statistics that say what their sampling costs. Conventions in glint_technique.h.
#pragma once

#include <array>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "formats/asset_writer.h"
#include "libbake/core/progress.h"
#include "formats/standardization_lut.h"
#include "libbake/image/normal_map.h"

namespace mbk {

struct LutChannelStatistics {
  double min = 0.0, max = 0.0;                    // the channel's range in the example
  uint64_t distinct_values = 0;                   // distinct float values (ties share a mid-rank)
  uint64_t knots = 0;                             // knots stored
  double gaussian_min = 0.0, gaussian_max = 0.0;  // [z_lo, z_hi] = [G(min), G(max)]
  // What the knots cost, against the exact transform (empirical_standardization.h):
  // max |G_T(x) - G(x)| over the example's distinct values x (Gaussian units), what a blend sees at texel centres;
  double forward_error = 0.0;
  // max |G^-1_T(z) - G^-1(z)| over the midpoints of the knot intervals in z and z_lo, z_hi (normal units);
  double inverse_error = 0.0;
  // max |G^-1_T(G_T(x)) - x| over the example's distinct values x, both through the knots (normal units).
  double round_trip_error = 0.0;
  // N(0, 1) mass outside the inverse table's range [z_lo, z_hi]: where blended values clamp to min or max.
  double clipped_tail_mass = 0.0;
  nlohmann::json to_json() const;
};

struct BakedLut {
  StandardizationLut tables;
  std::array<LutChannelStatistics, 2> statistics;  // n_x, n_y
};

// Standardizes both channels of `map` into knots at grid resolution `size` (2..65536). Deterministic
// whatever the thread count. Throws Error(bad_command_line) for a size out of range.
BakedLut bake_standardization_lut(const NormalMap& map, uint32_t size, Progress& progress);

// The asset: sections and metadata of formats/SPEC.md "Kind 2: lut" ("inputs" from `input`).
AssetWriter lut_asset_writer(const BakedLut& lut, const InputRecord& input);

}  // namespace mbk
