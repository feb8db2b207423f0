// The layout and lookup convention of asset kind 2, `lut` (standardization LUTs; formats/SPEC.md "Kind 2: lut"),
// shared by the baker (libbake/glint/standardization_sampling.h), the evaluator's lookups
// (formats/lut_lookup.h) and `validate` (formats/kind_lut.cpp), so that all three agree to the bit.
//
// Per channel c (0 = n_x, 1 = n_y) a lut asset holds two tables of `size` samples each:
// - forward:  G   on the example's value range [x_lo, x_hi] (values are Gaussian z),
// - inverse:  G^-1 on the Gaussian range [z_lo, z_hi] = [G(x_lo), G(x_hi)] (values are normal components),
// and, for each, a slope table of size - 1 entries: the exact derivative of its piecewise-linear interpolant.
//
// Lookup convention (the only one): sample j of a table over [lo, hi] sits at
//
//     s_j = lo + j (hi - lo) / (size - 1),      j = 0 .. size - 1      (s_0 = lo, s_{size-1} = hi exactly),
//
// i.e. texel centres of a 1-D texture of `size` texels whose first and last centres are lo and hi. Between
// samples the table is interpolated linearly; below lo it is the first sample and above hi the last (every index
// clamps). Slope entry j is (v_{j+1} - v_j) / ((hi - lo) / (size - 1)), the derivative on [s_j, s_{j+1}); 0 when
// lo == hi (then every sample is equal).
#pragma once

#include <cstdint>
#include <string_view>

namespace mbk {

inline constexpr uint32_t kLutKindId = 2;
inline constexpr uint32_t kLutMinSize = 2;
inline constexpr uint32_t kLutMaxSize = 65536;
inline constexpr uint32_t kLutDefaultSize = 4096;
inline constexpr uint32_t kLutChannels = 2;
inline constexpr std::string_view kLutChannelNames[kLutChannels] = {"n_x", "n_y"};

// Sections, all f32: domains [2, 4] holding (x_lo, x_hi, z_lo, z_hi) per channel; forward and inverse
// [2, size]; forward_slope and inverse_slope [2, size - 1].
inline constexpr std::string_view kLutDomainsSection = "domains";
inline constexpr std::string_view kLutForwardSection = "forward";
inline constexpr std::string_view kLutForwardSlopeSection = "forward_slope";
inline constexpr std::string_view kLutInverseSection = "inverse";
inline constexpr std::string_view kLutInverseSlopeSection = "inverse_slope";
inline constexpr uint32_t kLutDomainValues = 4;

// s_j above (exactly hi at j = size - 1).
double lut_sample_position(double lo, double hi, uint32_t size, uint32_t j);
// The slope of the interpolant between samples v0 = v_j and v1 = v_{j+1}; 0 when lo == hi.
double lut_interval_slope(double lo, double hi, uint32_t size, double v0, double v1);

}  // namespace mbk
