// Ray-shape intersection with uv and dp/du, dp/dv (parameterisations in shape_intersection.h).
#include "libbake/eval/shape_intersection.h"

#include <Eigen/Geometry>  // cross products

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

// The frame every shape shares: T (tangent, +u), B = N x T (+v), N (normal).
struct ShapeFrame {
  Vec3 T, B, N;
  explicit ShapeFrame(const Shape& s) : T(s.tangent), B(s.normal.cross(s.tangent)), N(s.normal) {}
};

std::optional<SurfaceHit> intersect_plane(const Shape& s, const Ray& ray, double t_max) {
  const ShapeFrame f(s);
  const double denom = ray.direction.dot(f.N);
  if (denom == 0.0) return std::nullopt;  // parallel: the ray never meets the plane (or lies in it, measure zero)
  const double t = (s.center - ray.origin).dot(f.N) / denom;
  if (!(t > 0.0 && t < t_max)) return std::nullopt;
  SurfaceHit h;
  h.t = t;
  h.p = ray.origin + t * ray.direction;
  const Vec3 local = h.p - s.center;
  const double a = local.dot(f.T) / s.size.x(), b = local.dot(f.B) / s.size.y();
  if (std::abs(a) > 0.5 || std::abs(b) > 0.5) return std::nullopt;
  h.normal = f.N;
  h.uv = Vec2((a + 0.5) * s.uv_scale.x(), (b + 0.5) * s.uv_scale.y());
  h.dpdu = f.T * (s.size.x() / s.uv_scale.x());
  h.dpdv = f.B * (s.size.y() / s.uv_scale.y());
  return h;
}

// Roots of t^2 + 2 b t + c = 0 in ascending order, computed without cancellation
// (q = -(b + sign(b) sqrt(b^2 - c)), roots q and c / q). False when there is no real root.
bool quadratic_roots(double b, double c, double disc, double& t0, double& t1) {
  if (disc < 0.0) return false;
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  t0 = q;
  t1 = q != 0.0 ? c / q : 0.0;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

std::optional<SurfaceHit> intersect_sphere(const Shape& s, const Ray& ray, double t_max) {
  const ShapeFrame f(s);
  const Vec3 oc = ray.origin - s.center;
  const double b = oc.dot(ray.direction);
  const double c = oc.squaredNorm() - s.radius * s.radius;
  // b^2 - c written as r^2 - |oc - b D|^2: the squared distance of the line from the centre does not
  // cancel catastrophically when the sphere is small and far away (pbrt-v4, 6.2.2).
  const double disc = s.radius * s.radius - (oc - b * ray.direction).squaredNorm();
  double t0, t1;
  if (!quadratic_roots(b, c, disc, t0, t1)) return std::nullopt;
  const double t = t0 > 0.0 ? t0 : t1;
  if (!(t > 0.0 && t < t_max)) return std::nullopt;
  SurfaceHit h;
  h.t = t;
  h.p = ray.origin + t * ray.direction;
  const Vec3 q = (h.p - s.center).normalized();
  const double qx = q.dot(f.T), qy = q.dot(f.B), qz = std::clamp(q.dot(f.N), -1.0, 1.0);
  double phi = std::atan2(qy, qx);
  if (phi < 0.0) phi += 2.0 * kPi;
  const double theta = std::acos(qz);
  const double sin_t = std::sin(theta), cos_t = qz, sin_p = std::sin(phi), cos_p = std::cos(phi);
  h.normal = q;
  h.uv = Vec2(phi / (2.0 * kPi) * s.uv_scale.x(), (1.0 - theta / kPi) * s.uv_scale.y());
  h.dpdu = (2.0 * kPi * s.radius / s.uv_scale.x()) * sin_t * (-sin_p * f.T + cos_p * f.B);
  h.dpdv = (kPi * s.radius / s.uv_scale.y()) * (-cos_t * cos_p * f.T - cos_t * sin_p * f.B + sin_t * f.N);
  return h;
}

std::optional<SurfaceHit> intersect_bent_quad(const Shape& s, const Ray& ray, double t_max) {
  const ShapeFrame f(s);
  const double angle = s.angle_degrees * kPi / 180.0;
  const double w = s.size.x(), height = s.size.y();
  const double R = w / angle;  // signed radius
  const Vec3 axis_point = s.center - R * f.N;
  // The cylinder |(p - axis_point) - ((p - axis_point) . B) B| = |R|, in the plane orthogonal to B.
  const Vec3 o = ray.origin - axis_point;
  const Vec3 o_perp = o - o.dot(f.B) * f.B;
  const Vec3 d_perp = ray.direction - ray.direction.dot(f.B) * f.B;
  const double a = d_perp.squaredNorm();
  if (a == 0.0) return std::nullopt;  // along the axis: never meets the cylinder's side
  const double b = o_perp.dot(d_perp) / a, c = (o_perp.squaredNorm() - R * R) / a;
  const double disc = (R * R - (o_perp - (o_perp.dot(d_perp) / a) * d_perp).squaredNorm()) / a;
  double roots[2];
  if (!quadratic_roots(b, c, disc, roots[0], roots[1])) return std::nullopt;
  for (double t : roots) {
    if (!(t > 0.0 && t < t_max)) continue;
    const Vec3 p = ray.origin + t * ray.direction;
    const Vec3 local = p - axis_point;
    const double phi = std::atan2(local.dot(f.T) / R, local.dot(f.N) / R);
    const double along = local.dot(f.B) / height;
    if (std::abs(phi) > 0.5 * std::abs(angle) || std::abs(along) > 0.5) continue;
    SurfaceHit h;
    h.t = t;
    h.p = p;
    h.normal = std::sin(phi) * f.T + std::cos(phi) * f.N;
    h.uv = Vec2((phi / angle + 0.5) * s.uv_scale.x(), (along + 0.5) * s.uv_scale.y());
    h.dpdu = (w / s.uv_scale.x()) * (std::cos(phi) * f.T - std::sin(phi) * f.N);
    h.dpdv = (height / s.uv_scale.y()) * f.B;
    return h;
  }
  return std::nullopt;
}

}  // namespace

std::optional<SurfaceHit> intersect_shape(const Shape& shape, const Ray& ray, double t_max) {
  switch (shape.type) {
    case ShapeType::plane:
      return intersect_plane(shape, ray, t_max);
    case ShapeType::sphere:
      return intersect_sphere(shape, ray, t_max);
    case ShapeType::bent_quad:
      return intersect_bent_quad(shape, ray, t_max);
  }
  return std::nullopt;
}

std::optional<SurfaceHit> intersect_scene(const std::vector<Shape>& shapes, const Ray& ray) {
  std::optional<SurfaceHit> nearest;
  for (size_t i = 0; i < shapes.size(); ++i) {
    auto h = intersect_shape(shapes[i], ray, nearest ? nearest->t : std::numeric_limits<double>::infinity());
    if (h) {
      h->shape = i;
      nearest = h;
    }
  }
  return nearest;
}

}  // namespace mbk
