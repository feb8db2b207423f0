// The MIP pyramid of a normal map (the box pyramid of box_pyramid.h on the three components): level 0 the unit
// normals, level k the unnormalised mean of the finest normals each texel covers (formats/mip_levels.h gives
// sizes and coverage). The mean's length is below 1 where normals disagree; Toksvig-style roughening reads it.
// Means accumulate in double.
#pragma once

#include <vector>

#include "libbake/image/normal_map.h"

namespace mbk {

struct NormalPyramid {
  std::vector<NormalMap> levels;  // levels[0] == the input map; texels of coarser levels are not unit length
};

// levels[0] is `map` itself (moved in when the caller passes an rvalue).
NormalPyramid build_normal_pyramid(NormalMap map);

// Trilinear lookup: bilinear within the two levels around `lod` (clamped to [0, levels-1]), wrapping at
// the borders (tiling), blended linearly; uv in the conventions of normal_map.h. Returns the unnormalised
// filtered mean normal. Non-finite uv or a NaN lod give NaN; an empty pyramid is Error(runtime_failure).
Vec3 sample_pyramid(const NormalPyramid& pyramid, const Vec2& uv, double lod);
// Bilinear lookup in one level, wrapping.
Vec3 sample_bilinear(const NormalMap& level, const Vec2& uv);

}  // namespace mbk
