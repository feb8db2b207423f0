// Pinhole camera rays and their differentials (see camera_rays.h for the derivation).
#include "libbake/eval/camera_rays.h"

#include <Eigen/Geometry>  // cross products

#include <cmath>
#include <numbers>

namespace mbk {

PinholeCamera::PinholeCamera(const Camera& c)
    : position_(c.position),
      forward_((c.look_at - c.position).normalized()),
      tan_half_fov_(std::tan(0.5 * c.fov_y_degrees * std::numbers::pi / 180.0)),
      width_(c.width),
      height_(c.height) {
  right_ = forward_.cross(c.up).normalized();
  up_ = right_.cross(forward_);
}

RayDifferential PinholeCamera::ray(double x, double y) const {
  const double aspect = double(width_) / double(height_);
  const double sx = (2.0 * x / width_ - 1.0) * tan_half_fov_ * aspect;
  const double sy = (1.0 - 2.0 * y / height_) * tan_half_fov_;
  const Vec3 d = forward_ + sx * right_ + sy * up_;
  const double len = d.norm();
  const Vec3 D = d / len;
  const double step = 2.0 * tan_half_fov_ / height_;  // |dd/dx| = |dd/dy|: square pixels
  const Vec3 ddx = step * right_, ddy = -step * up_;
  RayDifferential r;
  r.ray = {position_, D};
  r.ddx = (ddx - D * D.dot(ddx)) / len;
  r.ddy = (ddy - D * D.dot(ddy)) / len;
  return r;
}

}  // namespace mbk
