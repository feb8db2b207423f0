// The standardization tables of an example ([Wang20] Eq. 6 and appendix; [Heitz18] Sec. 3), per channel, as
// asset kind `lut` stores them (formats/lut_layout.h) and as the evaluator reads them: G and G^-1 sampled into
// float tables with their exact slope tables, looked up with lut_lookup.h. read_standardization_lut() needs only
// formats/ (no baker); the baker builds the same struct with sample_standardization().
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "formats/asset.h"
#include "formats/lut_lookup.h"

namespace mbk {

struct StandardizationChannelTables {
  // Domains: forward over [x_lo, x_hi] (the example's range), inverse over [z_lo, z_hi] = [G(x_lo), G(x_hi)].
  float x_lo = 0.0f, x_hi = 0.0f, z_lo = 0.0f, z_hi = 0.0f;
  std::vector<float> forward, forward_slope;  // size and size - 1
  std::vector<float> inverse, inverse_slope;  // size and size - 1

  LutTableView forward_table() const { return {x_lo, x_hi, forward, forward_slope}; }
  LutTableView inverse_table() const { return {z_lo, z_hi, inverse, inverse_slope}; }
  // G(x) and dG/dx; G^-1(z) and dG^-1/dz, through the tables.
  LutSample standardize(double x) const { return lut_lookup(forward_table(), x); }
  LutSample destandardize(double z) const { return lut_lookup(inverse_table(), z); }
};

struct StandardizationLut {
  uint32_t size = 0;                                     // samples per table
  std::array<StandardizationChannelTables, 2> channels;  // n_x, n_y
};

// The tables of a `lut` asset. Throws Error(invalid_input) naming the asset when it is another kind or its
// section shapes disagree (values are checked by `validate`; lookups clamp whatever they hold).
StandardizationLut read_standardization_lut(const Asset& asset);

}  // namespace mbk
