// Per-pixel texture footprints from ray differentials (Igehy 1999; pbrt-v4 10.1.1). At a hit point p
// with normal n, the neighbouring pixel's ray (direction D + dD/dx) meets the tangent plane of the surface
// at p + dp/dx, where, with dO/dx = 0 for a pinhole,
//     dp/dx = t dD/dx + (dt/dx) D,    dt/dx = -t (dD/dx . n) / (D . n)          [Igehy, Eq. 10]
// and dp/dx = dp/du du/dx + dp/dv dv/dx is solved for (du/dx, dv/dx) in the least-squares sense (the
// 2x2 normal equations of [dp/du dp/dv]); likewise for y. These are the uv-space derivatives duv/dx,
// duv/dy a GPU obtains from its 2x2 pixel quads.
//
// Anisotropic probes (footprint_probes): the footprint in texels is the image of the pixel under the
// Jacobian M = [duv/dx * (W, H), duv/dy * (W, H)] for a W x H map, an ellipse with semi-axes proportional to
// M's singular values s1 >= s2 (Heckbert 1989, the EWA ellipse; OpenGL's isotropic rule, 4.6 8.14.1, takes the
// longer column of M as its size instead).
// A lookup at the minor axis's level would be too sharp and one at the major axis's too blurred, so the
// footprint is covered, as GPU anisotropic filtering does (EXT_texture_filter_anisotropic), by N probes
//     N = min(max_probes, ceil(s1 / s2), ceil(s1)),   probe i at uv + ((i + 1/2) / N - 1/2) s1 u1 / (W, H),
// each a trilinear lookup of width w = max(s2, s1 / N) texels, equally weighted (a box pixel: the reference's
// pixel filter), u1 the major axis's unit direction in texels. The level for width w matches second moments:
// a level-k texel is the box mean of 2^k texels and the bilinear lookup adds a tent of half-width 2^k, a kernel
// of variance 4^k (1/12 + 1/6) = 4^k / 4 per axis, while the box of width w has w^2 / 12; equal for
//     lod = log2(w) - log2(sqrt(3))   (kLodOfBoxVariance = 0.79),
// clamped at 0 (magnification). (lod = log2(w), the OpenGL rule, filters twice the box's variance: at ~5 texels
// per pixel that alone doubled the filtered effects' error on the filtering report's middle sphere.) A circle (or
// max_probes = 1) gives one probe of width s1; magnification (s1 <= 1) one probe at level 0 of width s1. A footprint
// that is infinite (grazing rays) gives one probe at kMaxLod and infinite width, which every pyramid clamps to its
// coarsest level.
#pragma once

#include <array>
#include <span>

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
  // The viewer-facing surface normal's change per pixel step on a curved surface: the normals where the rays
  // half a step either side meet the same shape, differenced (zero where either misses it, or when no shape was
  // given: the renderer gives it only to shaders that use it). The glints effect turns it into the tangent frame's
  // turn over the pixel.
  Vec3 dnormal_dx = Vec3::Zero(), dnormal_dy = Vec3::Zero();
  // The cap on anisotropic probes per lookup (`render --max-probes`; 1 = isotropic filtering).
  int max_probes = 16;
};

inline constexpr double kMaxLod = 64.0;
inline constexpr double kLodOfBoxVariance = 0.79248125036057812;  // log2(sqrt(3)), see above
inline constexpr int kMaxFootprintProbes = 64;

// One lookup of an anisotropic footprint: where, at which level of detail, and the box width w it stands for
// (texels of the W x H map; +inf for a grazing ray). Trilinear lookups use lod; the glints P-NDF, which filters
// by a Gaussian footprint of its own, uses width.
struct FootprintProbe {
  Vec2 uv = Vec2::Zero();
  double lod = 0.0;
  double width = 0.0;
};

// The probes covering a footprint, each of weight 1 / size().
class FootprintProbes {
 public:
  void push_back(const FootprintProbe& p) { probes_[size_t(count_++)] = p; }
  int size() const { return count_; }
  const FootprintProbe* begin() const { return probes_.data(); }
  const FootprintProbe* end() const { return probes_.data() + count_; }

 private:
  std::array<FootprintProbe, kMaxFootprintProbes> probes_;
  int count_ = 0;
};

// `shape`, when given, is the shape that was hit: it fills dnormal_dx, dnormal_dy (two intersections per step).
UvFootprint uv_footprint(const SurfaceHit& hit, const RayDifferential& ray, const Shape* shape = nullptr);
// The anisotropic probes of the footprint at uv for a W x H map (see above). Non-finite footprints (grazing
// rays) give one probe at kMaxLod; max_probes is clamped to [1, kMaxFootprintProbes].
FootprintProbes footprint_probes(const Vec2& uv, const UvFootprint& footprint, uint32_t map_width, uint32_t map_height);

}  // namespace mbk
