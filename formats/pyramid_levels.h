// Reading the levels of a pyramid kind (`mip`, `moments`) for `validate`: sections level_0 .. level_{L-1}, each f32
// [h_k, w_k, channels] with the sizes of formats/mip_levels.h, no level beyond, every value finite.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "formats/mip_levels.h"
#include "formats/validation_messages.h"

namespace mbk {

class Asset;

// The levels' values, or nullopt after appending one finding: `shape` for a missing, mis-typed or mis-shaped level
// or one level too many, `non_finite` for a NaN or infinity (naming the level and element).
std::optional<std::vector<std::vector<float>>> read_pyramid_levels(const Asset& a, const std::vector<LevelSize>& sizes,
                                                                   uint64_t channels, const MessageInfo& shape,
                                                                   const MessageInfo& non_finite,
                                                                   std::vector<Finding>& out);

// The area-weighted mean of level 0 (W texels wide, `channels` per texel) over a level texel whose coverage along x
// and y is wx and wy (mip_texel_weights), accumulated in double: what every coarser texel must hold.
std::vector<double> level0_mean(const std::vector<float>& finest, uint32_t width, uint32_t channels,
                                const std::vector<MipWeight>& wx, const std::vector<MipWeight>& wy);

}  // namespace mbk
