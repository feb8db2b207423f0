// The standardization transform of an example ([Wang20] Eq. 6 and appendix; [Heitz18] Sec. 3), per channel, as
// asset kind `lut` stores it (formats/lut_layout.h) and as the evaluator reads it: knots (x_i, z_i) of G, looked
// up forward (G_T) and backward (G^-1_T) with lut_lookup.h. read_standardization_lut() needs only formats/ (no
// baker); the baker builds the same struct with sample_standardization().
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "formats/asset.h"
#include "formats/lut_lookup.h"

namespace mbk {

class StandardizationChannelTables {
 public:
  StandardizationChannelTables() = default;
  // Knots strictly increasing in x and z (not checked here: `validate` does; lookups stay in bounds regardless).
  StandardizationChannelTables(std::vector<float> x, std::vector<float> z);

  std::span<const float> x() const { return forward_.keys(); }
  std::span<const float> z() const { return forward_.values(); }
  size_t knots() const { return forward_.keys().size(); }
  // The domains: the example's range [x_lo, x_hi] and [z_lo, z_hi] = [G(x_lo), G(x_hi)].
  float x_lo() const { return x().front(); }
  float x_hi() const { return x().back(); }
  float z_lo() const { return z().front(); }
  float z_hi() const { return z().back(); }
  // G(x) and dG/dx; G^-1(z) and dG^-1/dz, through the knots.
  LutSample standardize(double x) const { return forward_(x); }
  LutSample destandardize(double z) const { return inverse_(z); }

 private:
  KnotInterpolant forward_, inverse_;
};

struct StandardizationLut {
  uint32_t size = 0;                                     // grid resolution the knots were made at
  std::array<StandardizationChannelTables, 2> channels;  // n_x, n_y
};

// The tables of a `lut` asset. Throws Error(invalid_input) naming the asset when it is another kind or its
// section shapes disagree (values are checked by `validate`; lookups clamp whatever they hold).
StandardizationLut read_standardization_lut(const Asset& asset);

}  // namespace mbk
