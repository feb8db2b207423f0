// Per-pixel texture footprints from ray differentials (Igehy 1999; pbrt-v4 10.1.1). At a hit point p
// with normal n, the neighbouring pixel's ray (direction D + dD/dx) meets the tangent plane of the surface
// at p + dp/dx, where, with dO/dx = 0 for a pinhole,
//     dp/dx = t dD/dx + (dt/dx) D,    dt/dx = -t (dD/dx . n) / (D . n)          [Igehy, Eq. 10]
// and dp/dx = dp/du du/dx + dp/dv dv/dx is solved for (du/dx, dv/dx) in the least-squares sense (the
// 2x2 normal equations of [dp/du dp/dv]); likewise for y. These are the uv-space derivatives duv/dx,
// duv/dy a GPU obtains from its 2x2 pixel quads.
//
// LOD: the footprint in texels is rho = max(|duv/dx * (W, H)|, |duv/dy * (W, H)|) for a W x H map (the
// isotropic rule of OpenGL 4.6, 8.14.1), and lod = log2(rho), clamped at 0 (magnification); a
// footprint that is infinite (grazing rays) gives kMaxLod, which the pyramid clamps to its coarsest level.
#pragma once

#include "libbake/eval/camera_rays.h"
#include "libbake/eval/shape_intersection.h"

namespace mbk {

struct UvFootprint {
  Vec2 duv_dx = Vec2::Zero(), duv_dy = Vec2::Zero();
  // The same pixel steps in world space: the hit point's dp/dx, dp/dy (Igehy Eq. 10, above) and the unit
  // direction to the viewer's, d(-D/|D|)/dx = -(dD/dx - d (d . dD/dx)) / |D| with d = D/|D| (pinhole: the
  // viewer does not move). The glints effect turns them into the half vector's sweep over the pixel.
  Vec3 dp_dx = Vec3::Zero(), dp_dy = Vec3::Zero();
  Vec3 dview_dx = Vec3::Zero(), dview_dy = Vec3::Zero();
};

inline constexpr double kMaxLod = 64.0;

UvFootprint uv_footprint(const SurfaceHit& hit, const RayDifferential& ray);
double mip_lod(const UvFootprint& footprint, uint32_t map_width, uint32_t map_height);

}  // namespace mbk
