// Ray-differential footprints: duv/dx and duv/dy equal the finite differences of the uv that neighbouring
// film positions' rays hit (tightly for tiny offsets, to first order for whole pixels); a plane seen head-on
// has the closed-form footprint. (The probes and levels of detail: anisotropic_footprint_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libbake/eval/uv_footprint.h"

namespace mbk {
namespace {

Scene footprint_scene() {
  Scene s;
  s.camera.position = Vec3(0.0, 1.5, 4.0);
  s.camera.look_at = Vec3(0.0, 0.4, 0.0);
  s.camera.up = Vec3::UnitY();
  s.camera.fov_y_degrees = 50;
  // Fine enough that a pixel is small against the sphere's curvature, so that whole-pixel differences are
  // nearly linear.
  s.camera.width = 256;
  s.camera.height = 192;
  Shape plane;
  plane.type = ShapeType::plane;
  plane.size = Vec2(40.0, 40.0);
  plane.uv_scale = Vec2(16.0, 10.0);
  Shape sphere;
  sphere.type = ShapeType::sphere;
  sphere.center = Vec3(-0.7, 0.7, 0.0);
  sphere.radius = 0.7;
  sphere.uv_scale = Vec2(3.0, 2.0);
  Shape bent;
  bent.type = ShapeType::bent_quad;
  bent.center = Vec3(1.0, 0.6, -0.5);
  bent.normal = Vec3::UnitZ();
  bent.size = Vec2(1.2, 1.0);
  bent.angle_degrees = 80;
  s.shapes = {plane, sphere, bent};
  return s;
}

// The uv hit through film point (x, y) on the given shape, if that shape is what the ray sees.
std::optional<Vec2> uv_at(const Scene& s, const PinholeCamera& cam, double x, double y, size_t shape) {
  const auto hit = intersect_scene(s.shapes, cam.ray(x, y).ray);
  if (!hit || hit->shape != shape) return std::nullopt;
  return hit->uv;
}

TEST(UvFootprint, MatchesFiniteDifferencesOfNeighbouringRays) {
  const Scene s = footprint_scene();
  const PinholeCamera cam(s.camera);
  int checked[3] = {0, 0, 0}, pixel_checked = 0;
  for (uint32_t y = 0; y < s.camera.height; ++y)
    for (uint32_t x = 0; x < s.camera.width; ++x) {
      const double fx = x + 0.5, fy = y + 0.5;
      const RayDifferential r = cam.ray(fx, fy);
      const auto hit = intersect_scene(s.shapes, r.ray);
      if (!hit) continue;
      const UvFootprint f = uv_footprint(*hit, r);
      // Tiny offsets: the derivative itself. Skip the sphere's u seam, where uv jumps by uv_scale.x.
      const double h = 1e-4;
      const auto xp = uv_at(s, cam, fx + h, fy, hit->shape), xm = uv_at(s, cam, fx - h, fy, hit->shape);
      const auto yp = uv_at(s, cam, fx, fy + h, hit->shape), ym = uv_at(s, cam, fx, fy - h, hit->shape);
      if (!xp || !xm || !yp || !ym) continue;  // at a silhouette or edge
      const Vec2 fd_x = (*xp - *xm) / (2 * h), fd_y = (*yp - *ym) / (2 * h);
      if (std::max(fd_x.cwiseAbs().maxCoeff(), fd_y.cwiseAbs().maxCoeff()) > 100) continue;  // across the seam
      const double scale = std::max(f.duv_dx.norm(), f.duv_dy.norm());
      EXPECT_LT((f.duv_dx - fd_x).norm(), 1e-3 * scale) << "pixel " << x << "," << y << " shape " << hit->shape;
      EXPECT_LT((f.duv_dy - fd_y).norm(), 1e-3 * scale) << "pixel " << x << "," << y << " shape " << hit->shape;
      ++checked[hit->shape];
      // Whole pixels: central differences of the neighbouring pixels' uv agree to second order where the
      // four neighbours see the same smooth, non-grazing part of the shape, away from the sphere's poles
      // (where u turns around the pole within a pixel).
      const auto right = uv_at(s, cam, fx + 1, fy, hit->shape), left = uv_at(s, cam, fx - 1, fy, hit->shape);
      const auto below = uv_at(s, cam, fx, fy + 1, hit->shape), above = uv_at(s, cam, fx, fy - 1, hit->shape);
      const bool near_pole = s.shapes[hit->shape].type == ShapeType::sphere &&
                             std::abs(hit->normal.dot(s.shapes[hit->shape].normal)) > 0.5;
      if (right && left && below && above && std::abs(r.ray.direction.dot(hit->normal)) > 0.3 && !near_pole) {
        const Vec2 px = (*right - *left) / 2, py = (*below - *above) / 2;
        if (std::max(px.cwiseAbs().maxCoeff(), py.cwiseAbs().maxCoeff()) > 0.5) continue;  // across the seam
        EXPECT_LT((px - f.duv_dx).norm(), 0.05 * scale) << "pixel " << x << "," << y << " shape " << hit->shape;
        EXPECT_LT((py - f.duv_dy).norm(), 0.05 * scale) << "pixel " << x << "," << y << " shape " << hit->shape;
        ++pixel_checked;
      }
    }
  EXPECT_GT(checked[0], 8000);
  EXPECT_GT(checked[1], 1500);
  EXPECT_GT(checked[2], 800);
  EXPECT_GT(pixel_checked, 8000);
}

TEST(UvFootprint, HeadOnPlaneHasTheClosedFormFootprint) {
  // Camera at distance d on the plane's normal: one pixel spans 2 d tan(fov/2) / H scene units at the
  // centre, i.e. that times uv_scale / size in uv.
  Scene s;
  const double d = 3.0, fov = 30.0;
  s.camera = {Vec3(0, 0, d), Vec3::Zero(), Vec3::UnitY(), fov, 101, 101};
  Shape plane;
  plane.normal = Vec3::UnitZ();
  plane.tangent = Vec3::UnitX();
  plane.size = Vec2(8.0, 5.0);
  plane.uv_scale = Vec2(2.0, 3.0);
  const PinholeCamera cam(s.camera);
  const RayDifferential r = cam.ray(50.5, 50.5);
  const auto hit = intersect_shape(plane, r.ray, INFINITY);
  ASSERT_TRUE(hit);
  const UvFootprint f = uv_footprint(*hit, r);
  const double pixel = 2 * d * std::tan(fov / 2 * std::numbers::pi / 180) / 101;
  EXPECT_NEAR(f.duv_dx.x(), pixel * 2.0 / 8.0, 1e-12);
  EXPECT_NEAR(f.duv_dx.y(), 0.0, 1e-12);
  EXPECT_NEAR(f.duv_dy.x(), 0.0, 1e-12);
  EXPECT_NEAR(f.duv_dy.y(), -pixel * 3.0 / 5.0, 1e-12);  // film y grows downwards, v upwards
}

TEST(UvFootprint, SpherePoleStaysFinite) {
  // At the pole dp/du = 0: the normal equations are singular; v's footprint must survive.
  Shape sphere;
  sphere.type = ShapeType::sphere;
  sphere.radius = 1.0;
  Scene s;
  s.camera = {Vec3(0, 5, 0), Vec3::Zero(), Vec3::UnitZ(), 20.0, 33, 33};
  const PinholeCamera cam(s.camera);
  const RayDifferential r = cam.ray(16.5, 16.5);
  const auto hit = intersect_shape(sphere, r.ray, INFINITY);
  ASSERT_TRUE(hit);
  const UvFootprint f = uv_footprint(*hit, r);
  EXPECT_TRUE(f.duv_dx.allFinite() && f.duv_dy.allFinite());
  EXPECT_GT(std::max(f.duv_dx.norm(), f.duv_dy.norm()), 0.0);
}

}  // namespace
}  // namespace mbk
