// The normal lookups of the baseline and of the `mip` effect (material_shaders.h picks one per material).
// The tangent-space normal looked up here is turned into world space by the surface frame (surface_frame.h)
// and renormalised.
//   no normal map         (0, 0, 1): the geometric normal
//   baseline (no effect)  plain MIP-mapped normal mapping: the pyramid is built in memory from the
//                         material's map (libbake/image/normal_pyramid.h), looked up trilinearly at the
//                         footprint's anisotropic probes (uv_footprint.h), averaged and renormalised
//   effect `mip`          the same lookup in the baked mip asset (mip_effect.h), read through formats/
//   --reference           the raw map's level 0, bilinear (no filtering): the footprint is resolved by
//                         tracing many sub-pixel rays instead
// A filtered mean normal can vanish where opposite normals cancel (a symmetric V-groove averaged over its
// period); it then falls back to (0, 0, 1) (covered by MaterialNormals.CancellingNormalsFallBackToZ).
#pragma once

#include <memory>

#include "libbake/eval/uv_footprint.h"
#include "libbake/image/normal_pyramid.h"

namespace mbk {

enum class NormalFilter { none, trilinear, bilinear_level0 };

struct MaterialNormals {
  NormalFilter filter = NormalFilter::none;
  std::shared_ptr<const NormalPyramid> pyramid;  // trilinear: every level; bilinear_level0: level 0 suffices
  // The unit tangent-space normal at uv for a pixel footprint.
  Vec3 lookup(const Vec2& uv, const UvFootprint& footprint) const;
};

}  // namespace mbk
