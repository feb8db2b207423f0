// The `mip` asset kind (formats/kind_mip.cpp, formats/SPEC.md "Kind 1: mip"): the MIP pyramid of a normal
// map (normal_pyramid.h), the baseline every filtering technique is compared with.
#pragma once

#include "formats/asset_writer.h"
#include "libbake/image/normal_map.h"
#include "libbake/image/normal_pyramid.h"

namespace mbk {

// Sections level_0 .. level_{L-1}, each f32 [height, width, 3]; metadata "parameters" {width, height,
// levels}, the normal-map "conventions", and "statistics" per level: mean, minimum and maximum length of
// the stored (unnormalised) mean normals, i.e. how much the normals under each texel disagree.
// The map is taken by value: its texels become level_0 without a copy when the caller moves it in.
AssetWriter bake_mip_asset(LoadedNormalMap input);

}  // namespace mbk
