// Ray-differential footprints in uv and the MIP level they select (see uv_footprint.h).
#include "libbake/eval/uv_footprint.h"

#include <algorithm>
#include <cmath>

namespace mbk {
namespace {

// (du, dv) minimising |dp - du dp/du - dv dp/dv|. When the parameterisation is degenerate (dp/du = 0 at a
// sphere's pole) the normal equations are singular; each axis then takes its own projection (zero for a
// vanishing derivative), which keeps the other axis's footprint meaningful.
Vec2 solve_uv(const SurfaceHit& h, const Vec3& dp) {
  const double a11 = h.dpdu.squaredNorm(), a12 = h.dpdu.dot(h.dpdv), a22 = h.dpdv.squaredNorm();
  const double r1 = h.dpdu.dot(dp), r2 = h.dpdv.dot(dp);
  const double det = a11 * a22 - a12 * a12;
  // det relative to a11 a22 is sin^2 of the angle between dp/du and dp/dv: below 1e-12 they are parallel
  // to rounding and the solve would amplify noise by 1e12.
  if (det > 1e-12 * a11 * a22) return Vec2((a22 * r1 - a12 * r2) / det, (a11 * r2 - a12 * r1) / det);
  return Vec2(a11 > 0.0 ? r1 / a11 : 0.0, a22 > 0.0 ? r2 / a22 : 0.0);
}

Vec3 transfer(const SurfaceHit& h, const Vec3& D, const Vec3& dD) {
  const Vec3 at_same_t = h.t * dD;                               // where the neighbouring ray is at the same distance t
  const double dt = -at_same_t.dot(h.normal) / D.dot(h.normal);  // +-inf or NaN at grazing incidence, caught by mip_lod
  return at_same_t + dt * D;
}

}  // namespace

UvFootprint uv_footprint(const SurfaceHit& hit, const RayDifferential& ray) {
  const Vec3& D = ray.ray.direction;
  const Vec3 dp_dx = transfer(hit, D, ray.ddx), dp_dy = transfer(hit, D, ray.ddy);
  const double length = D.norm();
  const Vec3 d = D / length;
  const auto view_step = [&](const Vec3& dD) -> Vec3 { return -(dD - d * d.dot(dD)) / length; };
  return {solve_uv(hit, dp_dx), solve_uv(hit, dp_dy), dp_dx, dp_dy, view_step(ray.ddx), view_step(ray.ddy)};
}

double mip_lod(const UvFootprint& f, uint32_t map_width, uint32_t map_height) {
  const Vec2 size(map_width, map_height);
  const double rho = std::max(f.duv_dx.cwiseProduct(size).norm(), f.duv_dy.cwiseProduct(size).norm());
  if (!std::isfinite(rho)) return kMaxLod;  // grazing ray: the footprint is unbounded
  if (!(rho > 1.0)) return 0.0;             // magnification (also rho == 0 for a degenerate footprint)
  return std::min(std::log2(rho), kMaxLod);
}

}  // namespace mbk
