// Knots of the standardization transform of one channel (empirical_standardization.h) as asset kind `lut` stores
// them (formats/lut_layout.h): the exact G at the union of
//   - the uniform x grid of `size` points over [x_lo, x_hi] = [min, max],
//   - the points x = G^-1(z) of the uniform z grid of `size` points over [z_lo, z_hi] = [G(min), G(max)],
//   - every heavy value, one shared by at least N / size texels (an atom of the distribution),
// rounded to float, sorted, with repeated x or z dropped (keeping the ends and atoms). Forward G_T and inverse
// G^-1_T interpolate the same knots
// (lut_lookup.h), so they are exact inverses: G^-1_T(G_T(x)) = x up to double rounding, for every x.
//
// Why both grids and the atoms ([Wang20] samples G and G^-1 uniformly, 128 each; microbake 0.1 did too, 4096):
// where many texels share one value x0 (the flat ground of `scratches`: ~93% of texels), G rises from
// Phi^-1(0.03) to Phi^-1(0.97) within the few ulps between x0 and its neighbours, and a forward table sampled
// uniformly in x interpolates across that rise: G_T(x0) came out +0.61, +1.29 or -1.08 depending on the table size,
// where G(x0) = 0.0004, so every blend around a flat texel left the plateau. Here x0 is a knot, exact; the z grid
// puts knots on the steep rise; the x grid on the sparse stretches. Between consecutive knots, G and G_T are
// monotone and agree at both ends, so
//
//       +-----------------------------------------------------------------------------------------------+
//       |  |G_T(x) - G(x)| <= the knot interval's z step,   |G^-1_T(z) - G^-1(z)| <= its x step,          |
//       |  each at most one grid step (z_hi - z_lo) / (size - 1), (x_hi - x_lo) / (size - 1), up to float   |
//       |  rounding of the knots; G_T = G (to float) at every atom.                                         |
//       +-----------------------------------------------------------------------------------------------+
//
// The one exception is float resolution itself: where G rises by more than a z step between two adjacent floats
// (next to an atom of a large map), no float knot can sit in between, and that interval is one segment.
//
// A channel whose values all lie within kFlatChannelSpread of each other is stored as one knot (min, 0), exactly
// like a constant channel (G = 0, G^-1 = min): slopes across a spread of 1e-40 would exceed the float range, and
// the error made, below 1e-20 in normal units, is far under anything a float can show.
#pragma once

#include <cstdint>

#include "formats/standardization_lut.h"
#include "libbake/glint/empirical_standardization.h"

namespace mbk {

inline constexpr double kFlatChannelSpread = 1e-20;

StandardizationChannelTables sample_standardization(const EmpiricalStandardization& transform, uint32_t size);

}  // namespace mbk
