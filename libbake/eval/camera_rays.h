// Primary rays of the pinhole camera, with ray differentials (Igehy, "Tracing Ray Differentials",
// SIGGRAPH 1999): the derivatives of the unit ray direction with respect to the film coordinates x (right)
// and y (down), one pixel being one unit. A pinhole's rays share one origin, so dO/dx = dO/dy = 0.
//
// Film: pixel (i, j) covers [i, i+1] x [j, j+1], row j = 0 at the top. The image plane sits at distance 1
// along the forward axis f; a film point (x, y) maps to d = f + sx r + sy u with
//   sx = (2x/W - 1) tan(fov/2) W/H,   sy = (1 - 2y/H) tan(fov/2),
// r = normalize(f x up), u = r x f, and the ray direction is D = d / |d|. Differentiating,
//   dD/dx = (dd/dx - D (D . dd/dx)) / |d|,  dd/dx = (2 tan(fov/2) / H) r,  dd/dy = -(2 tan(fov/2) / H) u.
#pragma once

#include "libbake/core/eigen.h"
#include "libbake/scene/scene.h"

namespace mbk {

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit
};

struct RayDifferential {
  Ray ray;
  Vec3 ddx, ddy;  // dD/dx, dD/dy per pixel
};

class PinholeCamera {
 public:
  explicit PinholeCamera(const Camera& camera);
  // The ray through film point (x, y), e.g. (i + 0.5, j + 0.5) for the centre of pixel (i, j).
  RayDifferential ray(double x, double y) const;
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  Vec3 position_, forward_, right_, up_;
  double tan_half_fov_;
  uint32_t width_, height_;
};

}  // namespace mbk
