// Where each material's shading normal comes from. The tangent-space normal looked up here is turned into
// world space by the surface frame (surface_frame.h) and renormalised.
//   no normal map         (0, 0, 1): the geometric normal
//   baseline (no effect)  plain MIP-mapped normal mapping: the pyramid is built in memory from the
//                         material's map (libbake/image/normal_pyramid.h), looked up trilinearly at the
//                         footprint's LOD (uv_footprint.h) and renormalised
//   effect `mip`          the same lookup in the baked mip asset (mip_effect.h), read through formats/
//   --reference           the raw map's level 0, bilinear (no filtering): the footprint is resolved by
//                         tracing many sub-pixel rays instead
// A filtered mean normal can vanish where opposite normals cancel (a symmetric V-groove averaged over its
// period); it then falls back to (0, 0, 1) (covered by MaterialNormals.CancellingNormalsFallBackToZ).
//
// Assets: a material's effects are looked up in the bake plan (libbake/scene/bake_plan.h) inside the asset
// folder. A missing asset is Error(io_failure) pointing at `microbake bake`; an asset that no longer matches
// its normal map (when the map is present to compare) is Error(invalid_input), likewise.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "libbake/eval/uv_footprint.h"
#include "libbake/image/normal_pyramid.h"
#include "libbake/scene/scene.h"

namespace mbk {

enum class NormalFilter { none, trilinear, bilinear_level0 };

struct MaterialNormals {
  NormalFilter filter = NormalFilter::none;
  std::shared_ptr<const NormalPyramid> pyramid;  // trilinear: every level; bilinear_level0: level 0 suffices
  // The unit tangent-space normal at uv for a pixel footprint.
  Vec3 lookup(const Vec2& uv, const UvFootprint& footprint) const;
};

enum class NormalSource { effects, reference };

// One entry per material of the scene. Maps and assets shared by several materials are loaded once.
std::map<std::string, MaterialNormals> load_material_normals(const Scene& scene, NormalSource source,
                                                             const std::filesystem::path& asset_folder);

}  // namespace mbk
