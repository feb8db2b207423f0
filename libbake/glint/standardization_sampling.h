// Sampling the standardization transform of one channel (empirical_standardization.h) into the float tables of
// asset kind `lut` (formats/lut_layout.h): the inverse table G^-1 on [z_lo, z_hi] = [G(min), G(max)] and the
// forward table on [x_lo, x_hi] = [min, max], `size` samples each ([Wang20] uses 128; microbake defaults to
// 4096), and their slope tables, computed from the stored float samples so that they are the exact derivatives of
// the interpolants a lookup sees (lut_lookup.h).
//
// The two tables are made consistent with each other, because what blending needs is that a single patch comes
// back unchanged: G^-1_T(G_T(x)) = x, T marking the tables.
// - The inverse table samples the exact G^-1 at its sample positions (evaluated in double from the float domain
//   ends, rounded to float).
// - The forward table samples the exact inverse of the inverse table's interpolant, G_T(x_i) = (G^-1_T)^-1(x_i)
//   (where that interpolant is flat at x_i, the middle of the flat run, as mid-ranks do for ties). Then for any
//   x in [x_i, x_{i+1}], G_T(x) lies between G_T(x_i) and G_T(x_{i+1}), and the monotone G^-1_T maps it back
//   between x_i and x_{i+1}:
//
//       +---------------------------------------------------------------------------------+
//       |  |G^-1_T(G_T(x)) - x| <= h_x = (max - min) / (size - 1)   (+ float rounding)     |
//       +---------------------------------------------------------------------------------+
//
//   for every x, whatever the distribution: at most 4.9e-4 in normal units at the default size (a channel spans
//   at most [-1, 1]), 1.6e-2 at 128 (tests: StandardizationLut.RoundTripWithinOneForwardStep*).
//   Deviation [Heitz18], [Wang20]: sampling G itself instead leaves the round trip at the mercy of the inverse
//   table's interpolation where G^-1 jumps between sparse example values within one table step: 1.8e-3 on
//   `flakes` at 4096 samples. G_T stays within one inverse step of G wherever G^-1 is resolved; near an atom
//   (many texels of one value, e.g. the flat ground of `scratches`) G is nearly vertical and no uniform x
//   sampling can follow it, with either construction.
// - Both tables are non-decreasing (float rounding is monotone), and their end samples are pinned to the other
//   table's domain ends (forward: z_lo, z_hi; inverse: x_lo, x_hi): G^-1(G(min)) = min exactly, whereas evaluating
//   G^-1 at the float-rounded z_lo could land an ulp beside min.
// - Outside [z_lo, z_hi] the exact G^-1 is the clamped end value, so the inverse table loses nothing by its range;
//   the Gaussian mass clamped there is the channel's clipped tail mass.
// - A channel whose values all lie within kFlatChannelSpread of each other is stored as the constant min (G = 0,
//   G^-1 = min, zero slopes), exactly like a constant channel: its slope dG/dx would otherwise exceed the float
//   range (a spread of 1e-40 with 4096 samples gives slopes ~1e44), and the error made, below 1e-20 in normal
//   units, is far under anything a float can show (test: StandardizationLut.NearlyConstantChannelStaysFinite).
#pragma once

#include <cstdint>

#include "libbake/glint/empirical_standardization.h"
#include "formats/standardization_lut.h"

namespace mbk {

inline constexpr double kFlatChannelSpread = 1e-20;

StandardizationChannelTables sample_standardization(const EmpiricalStandardization& transform, uint32_t size);

}  // namespace mbk
