// The MIP level rule shared by every pyramid microbake bakes (normal MIP pyramids here; SH and vMF
// pyramids later). Level 0 is the full W x H image; level k has max(1, floor(W / 2^k)) x max(1, floor(H / 2^k))
// texels (the size a GPU allocates for mip level k), down to 1 x 1: L = 1 + floor(log2(max(W, H))) levels.
// Texel i of a level of w texels along an axis of W finest texels covers the finest-texel interval
// [i W / w, (i+1) W / w), so the level's texels divide the image (and uv in [0, 1]) evenly and a lookup at a
// texel's centre sees what the texel covers. A texel holds the area-weighted mean over its rectangle: finest
// texels it covers partly count with the covered fraction. The weights are separable (overlap along x times
// overlap along y); for power-of-two sizes they reduce to plain 2^k x 2^k box means.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace mbk {

struct LevelSize {
  uint32_t width, height;
};

// Empty when width or height is 0.
std::vector<LevelSize> mip_level_sizes(uint32_t width, uint32_t height);

// The level sizes a `mip` asset's metadata "parameters" describe: "width" and "height" integers in 1..2^32 - 1,
// and "levels" equal to the number of levels of that size (mip_level_sizes). Returns "" and sets `sizes` when
// they are, else what is wrong, telling a missing key from a wrong value and showing the value:
// "parameters.width is missing", "parameters.width is -4, not an integer in 1..4294967295",
// "parameters.levels is 3, but a 16x16 pyramid has 5 levels". The one reading of these parameters, shared by
// `validate` (formats/kind_mip.cpp) and the evaluator (libbake/eval/mip_effect.cpp).
std::string parse_mip_parameters(const nlohmann::json& parameters, std::vector<LevelSize>& sizes);

// One finest texel under a level texel along an axis, and its share of the texel's length.
struct MipWeight {
  uint32_t index;  // finest texel along the axis
  double weight;   // overlap length / texel length, in (0, 1]; a texel's weights sum to 1
};

// For an axis of `extent` finest texels shown by `level_extent` texels (1 <= level_extent <= extent, else
// Error(runtime_failure)): per level texel, the finest texels it overlaps in increasing order with their
// weights. The mean of texel (i, j) is sum over x-list(i), y-list(j) of weight_x weight_y finest(x, y).
std::vector<std::vector<MipWeight>> mip_texel_weights(uint32_t level_extent, uint32_t extent);

// Whether `name` is "level_<k>" for a decimal k: the section names of every pyramid kind (mip, moments).
bool is_level_section_name(const std::string& name);

}  // namespace mbk
