// Ray-differential footprints in uv and the anisotropic probes that filter them (see uv_footprint.h).
#include "libbake/eval/uv_footprint.h"

#include <algorithm>
#include <cmath>
#include <optional>

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
  const double dt = -at_same_t.dot(h.normal) / D.dot(h.normal);  // +-inf or NaN at grazing incidence (footprint_probes)
  return at_same_t + dt * D;
}

// The viewer-facing normal's change over one pixel step dD of the ray direction (uv_footprint.h).
Vec3 normal_step(const Shape& shape, const Ray& ray, const Vec3& dD) {
  const auto facing_normal = [&](double side) -> std::optional<Vec3> {
    const Vec3 d = (ray.direction + side * 0.5 * dD).normalized();
    const auto hit = intersect_shape(shape, Ray{ray.origin, d}, INFINITY);
    if (!hit) return std::nullopt;
    return hit->normal.dot(d) < 0.0 ? hit->normal : Vec3(-hit->normal);
  };
  const auto plus = facing_normal(1.0), minus = facing_normal(-1.0);
  return plus && minus && dD.allFinite() ? Vec3(*plus - *minus) : Vec3::Zero();
}

}  // namespace

UvFootprint uv_footprint(const SurfaceHit& hit, const RayDifferential& ray, const Shape* shape) {
  const Vec3& D = ray.ray.direction;
  const Vec3 dp_dx = transfer(hit, D, ray.ddx), dp_dy = transfer(hit, D, ray.ddy);
  const double length = D.norm();
  const Vec3 d = D / length;
  const auto view_step = [&](const Vec3& dD) -> Vec3 { return -(dD - d * d.dot(dD)) / length; };
  UvFootprint f{solve_uv(hit, dp_dx), solve_uv(hit, dp_dy), dp_dx, dp_dy, view_step(ray.ddx), view_step(ray.ddy)};
  if (shape) {
    f.dnormal_dx = normal_step(*shape, ray.ray, ray.ddx);
    f.dnormal_dy = normal_step(*shape, ray.ray, ray.ddy);
  }
  return f;
}

FootprintProbes footprint_probes(const Vec2& uv, const UvFootprint& f, uint32_t map_width, uint32_t map_height) {
  FootprintProbes probes;
  const Vec2 size(map_width, map_height);
  const Vec2 a = f.duv_dx.cwiseProduct(size), b = f.duv_dy.cwiseProduct(size);
  if (!a.allFinite() || !b.allFinite()) {
    probes.push_back({uv, kMaxLod, INFINITY});  // grazing ray: the footprint is unbounded
    return probes;
  }
  // M M^T = a a^T + b b^T = [[pxx, q], [q, pyy]]; its eigenvalues are s1^2 >= s2^2. s2^2 = det(M)^2 / s1^2 avoids
  // the cancellation of (pxx + pyy - h) / 2 for thin ellipses.
  const double pxx = a.x() * a.x() + b.x() * b.x(), pyy = a.y() * a.y() + b.y() * b.y();
  const double q = a.x() * a.y() + b.x() * b.y();
  const double h = std::hypot(pxx - pyy, 2.0 * q);
  const double s1_sq = 0.5 * (pxx + pyy + h);
  const double s1 = std::sqrt(s1_sq);
  const double det = a.x() * b.y() - a.y() * b.x();
  const double s2 = s1 > 0.0 ? std::abs(det) / s1 : 0.0;
  if (!(s1 > 1.0)) {  // magnification, or a degenerate footprint
    probes.push_back({uv, 0.0, s1});
    return probes;
  }
  const int cap = std::clamp(f.max_probes, 1, kMaxFootprintProbes);
  const double ratio = s2 > 0.0 ? s1 / s2 : double(cap);
  const int n = int(std::min({double(cap), std::ceil(ratio - 1e-9), std::ceil(s1)}));
  const double width = std::max(s2, s1 / n);
  const double lod = std::clamp(std::log2(width) - kLodOfBoxVariance, 0.0, kMaxLod);
  if (n == 1) {
    probes.push_back({uv, lod, width});
    return probes;
  }
  // The major axis: the eigenvector of M M^T for s1^2, from whichever row of (M M^T - s1^2 I) is larger.
  Vec2 axis = std::abs(pxx - s1_sq) > std::abs(pyy - s1_sq) ? Vec2(q, s1_sq - pxx) : Vec2(s1_sq - pyy, q);
  const double len = axis.norm();
  axis = len > 0.0 ? Vec2(axis / len) : Vec2(1.0, 0.0);
  const Vec2 step = (s1 * axis).cwiseQuotient(size);  // the major axis's full length, in uv
  for (int i = 0; i < n; ++i) probes.push_back({uv + ((i + 0.5) / n - 0.5) * step, lod, width});
  return probes;
}

}  // namespace mbk
