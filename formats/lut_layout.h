// The layout of asset kind 10, `lut` (standardization knot tables; formats/SPEC.md "Kind 10: lut"), shared by the
// baker (libbake/glint/standardization_sampling.h), the evaluator's lookups (formats/lut_lookup.h) and `validate`
// (formats/kind_lut.cpp), so that all three agree to the bit.
//
// Per channel c (n_x, n_y) a lut asset holds one section `knots_<channel>` of M rows (x_i, z_i), f32: knots of the
// standardization transform G of that channel (z_i = G(x_i), rounded to float), strictly increasing in x and in z.
// The forward map G_T is the piecewise-linear interpolant through (x_i, z_i); the inverse map G^-1_T is the one
// through (z_i, x_i): the same segments read the other way, so the two are exact inverses of each other. One knot
// (M = 1) is a constant channel: G_T = z_0 = 0 and G^-1_T = x_0 everywhere.
//
// Parameter `size` (2..65536) is the resolution of the two uniform grids the knots come from (x over [x_lo, x_hi],
// z over [z_lo, z_hi]), with the example's heavily repeated values added exactly; so 1 <= M <= 3 size.
//
// Kind 2 was the same transform as uniform forward and inverse tables (microbake 0.1). Its forward table could not
// follow G across a value shared by many texels (G jumps there), so blends through it rendered another surface;
// kind 2 is retired and refused with a message to rebake.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace mbk {

inline constexpr uint32_t kLutKindId = 10;
inline constexpr uint32_t kRetiredLutKindId = 2;
inline constexpr uint32_t kLutMinSize = 2;
inline constexpr uint32_t kLutMaxSize = 65536;
inline constexpr uint32_t kLutDefaultSize = 4096;
inline constexpr uint32_t kLutChannels = 2;
inline constexpr std::string_view kLutChannelNames[kLutChannels] = {"n_x", "n_y"};
inline constexpr std::string_view kLutKnotSections[kLutChannels] = {"knots_n_x", "knots_n_y"};
inline constexpr uint32_t kLutKnotColumns = 2;  // (x, z)

// The most knots a channel of a table of `size` may have: two uniform grids and at most size heavy values.
inline constexpr uint64_t lut_max_knots(uint32_t size) { return 3 * uint64_t(size); }

// parameters.size of a lut asset's metadata when it is an unsigned integer in 2..65536; nullopt otherwise.
std::optional<uint32_t> lut_size_parameter(const nlohmann::json& metadata);
// Whether a knot section of an asset with parameter `size` has the shape [M, 2], 1 <= M <= lut_max_knots(size).
bool lut_knot_shape_ok(const std::vector<uint64_t>& shape, uint32_t size);

// Sample j of the uniform grid of `size` points over [lo, hi]: lo + j (hi - lo) / (size - 1), exactly hi at
// j = size - 1.
double lut_sample_position(double lo, double hi, uint32_t size, uint32_t j);

}  // namespace mbk
