// Ray-shape intersection: hits land on the surface at the parameterisation's point for their uv (the
// closed forms of shape_intersection.h, written out again here), dp/du and dp/dv are the derivatives of
// that parameterisation (central finite differences), the normal is along dp/du x dp/dv, and rays past
// the edges miss.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "libbake/eval/shape_intersection.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

// The shape's point at uv (uv already scaled by uv_scale), straight from the documented parameterisation.
Vec3 point_at(const Shape& s, const Vec2& uv) {
  const Vec3 T = s.tangent, N = s.normal, B = N.cross(T);
  const double u = uv.x() / s.uv_scale.x(), v = uv.y() / s.uv_scale.y();
  switch (s.type) {
    case ShapeType::plane:
      return s.center + (u - 0.5) * s.size.x() * T + (v - 0.5) * s.size.y() * B;
    case ShapeType::sphere: {
      const double phi = 2 * kPi * u, theta = kPi * (1 - v);
      return s.center + s.radius * (std::sin(theta) * std::cos(phi) * T + std::sin(theta) * std::sin(phi) * B +
                                    std::cos(theta) * N);
    }
    case ShapeType::bent_quad: {
      const double a = s.angle_degrees * kPi / 180, R = s.size.x() / a, phi = (u - 0.5) * a;
      return s.center + R * std::sin(phi) * T + R * (std::cos(phi) - 1) * N + (v - 0.5) * s.size.y() * B;
    }
  }
  return Vec3::Zero();
}

std::vector<Shape> test_shapes() {
  std::vector<Shape> shapes(5);
  shapes[0].type = ShapeType::plane;
  shapes[0].center = Vec3(0.3, -0.2, 0.1);
  shapes[0].normal = Vec3(0.2, 1.0, 0.3).normalized();
  shapes[0].tangent = (Vec3::UnitX() - Vec3::UnitX().dot(shapes[0].normal) * shapes[0].normal).normalized();
  shapes[0].size = Vec2(3.0, 2.0);
  shapes[0].uv_scale = Vec2(4.0, 3.0);
  shapes[1].type = ShapeType::sphere;
  shapes[1].center = Vec3(0.1, 0.2, -0.3);
  shapes[1].radius = 0.8;
  shapes[1].normal = Vec3(0.0, 0.6, 0.8);
  shapes[1].tangent = Vec3(1.0, 0.0, 0.0);
  shapes[1].uv_scale = Vec2(2.0, 1.0);
  for (int i : {2, 3, 4}) {
    shapes[i].type = ShapeType::bent_quad;
    shapes[i].normal = Vec3(0.0, 0.0, 1.0);
    shapes[i].tangent = Vec3(1.0, 0.0, 0.0);
    shapes[i].size = Vec2(1.5, 1.0);
    shapes[i].uv_scale = Vec2(2.0, 3.0);
  }
  shapes[2].angle_degrees = 90;    // convex
  shapes[3].angle_degrees = -120;  // concave
  shapes[4].angle_degrees = 300;   // nearly a full cylinder
  return shapes;
}

// Rays from outside aimed at surface points of random uv; the first hit must be that point.
TEST(ShapeIntersection, HitsLandOnTheParameterisationPointOfTheirUv) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  for (const Shape& s : test_shapes()) {
    for (int k = 0; k < 200; ++k) {
      const Vec2 uv(unit(rng) * s.uv_scale.x(), unit(rng) * s.uv_scale.y());
      const Vec3 target = point_at(s, uv);
      const Vec3 dpdu = point_at(s, uv + Vec2(1e-6, 0)) - point_at(s, uv - Vec2(1e-6, 0));
      const Vec3 dpdv = point_at(s, uv + Vec2(0, 1e-6)) - point_at(s, uv - Vec2(0, 1e-6));
      const Vec3 outward = dpdu.cross(dpdv).normalized();
      // Start on the outward side, close enough that nothing else of the shape is in between.
      const Vec3 origin = target + 0.05 * (outward + 0.3 * dpdu.normalized());
      const Ray ray{origin, (target - origin).normalized()};
      const auto hit = intersect_shape(s, ray, INFINITY);
      ASSERT_TRUE(hit) << "shape type " << int(s.type) << " uv " << uv.transpose();
      EXPECT_LT((hit->p - target).norm(), 1e-9);
      // The sphere's u wraps: compare positions rather than raw u there.
      EXPECT_LT((point_at(s, hit->uv) - target).norm(), 1e-9)
          << "uv " << hit->uv.transpose() << " vs " << uv.transpose();
      EXPECT_NEAR(hit->t, (target - origin).norm(), 1e-9);
    }
  }
}

TEST(ShapeIntersection, UvDerivativesMatchFiniteDifferences) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  for (const Shape& s : test_shapes()) {
    for (int k = 0; k < 100; ++k) {
      const Vec2 uv(unit(rng) * s.uv_scale.x(), unit(rng) * s.uv_scale.y());
      const Vec3 target = point_at(s, uv);
      const Vec3 away =
          (point_at(s, uv + Vec2(1e-6, 0)) - target).cross(point_at(s, uv + Vec2(0, 1e-6)) - target).normalized();
      const auto hit = intersect_shape(s, Ray{target + 0.1 * away, -away}, INFINITY);
      ASSERT_TRUE(hit);
      const double h = 1e-5;
      const Vec3 fd_u = (point_at(s, hit->uv + Vec2(h, 0)) - point_at(s, hit->uv - Vec2(h, 0))) / (2 * h);
      const Vec3 fd_v = (point_at(s, hit->uv + Vec2(0, h)) - point_at(s, hit->uv - Vec2(0, h))) / (2 * h);
      EXPECT_LT((hit->dpdu - fd_u).norm(), 1e-6 * (1 + fd_u.norm()))
          << hit->dpdu.transpose() << " vs " << fd_u.transpose();
      EXPECT_LT((hit->dpdv - fd_v).norm(), 1e-6 * (1 + fd_v.norm()))
          << hit->dpdv.transpose() << " vs " << fd_v.transpose();
      // Outward normal along dp/du x dp/dv: the tangent space of normal_map.h is right-handed.
      EXPECT_LT((hit->normal - hit->dpdu.cross(hit->dpdv).normalized()).norm(), 1e-9);
      EXPECT_NEAR(hit->normal.norm(), 1.0, 1e-12);
    }
  }
}

TEST(ShapeIntersection, RaysPastTheEdgesMiss) {
  const auto shapes = test_shapes();
  for (const Shape& s : {shapes[0], shapes[2], shapes[3]}) {
    for (const Vec2& outside : {Vec2(-0.01, 0.5), Vec2(1.01, 0.5), Vec2(0.5, -0.01), Vec2(0.5, 1.01)}) {
      // Aim from the side of the surface's normal at a point just beyond an edge (the formula extends there).
      const Vec3 target = point_at(s, outside.cwiseProduct(s.uv_scale));
      const Vec3 origin = target + 2.0 * s.normal;
      EXPECT_FALSE(intersect_shape(s, Ray{origin, (target - origin).normalized()}, INFINITY)) << outside.transpose();
    }
  }
}

TEST(ShapeIntersection, SceneReturnsTheNearestShapeAndRespectsDirection) {
  std::vector<Shape> shapes(2);
  shapes[0].type = shapes[1].type = ShapeType::sphere;
  shapes[0].center = Vec3(0, 0, -5);
  shapes[1].center = Vec3(0, 0, -2);
  shapes[0].radius = shapes[1].radius = 0.5;
  const auto hit = intersect_scene(shapes, Ray{Vec3::Zero(), Vec3(0, 0, -1)});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->shape, 1u);
  EXPECT_NEAR(hit->t, 1.5, 1e-12);
  EXPECT_FALSE(intersect_scene(shapes, Ray{Vec3::Zero(), Vec3(0, 0, 1)}));  // both behind the origin
  // From inside a sphere the exit point is hit.
  const auto inside = intersect_shape(shapes[1], Ray{Vec3(0, 0, -2), Vec3(1, 0, 0)}, INFINITY);
  ASSERT_TRUE(inside);
  EXPECT_NEAR(inside->t, 0.5, 1e-12);
}

TEST(ShapeIntersection, FarSmallSphereKeepsItsPrecision) {
  // |oc|^2 - r^2 cancels for a far, small sphere; the distance-to-line form of the discriminant does not.
  Shape s;
  s.type = ShapeType::sphere;
  s.center = Vec3(0, 0, -1e6);
  s.radius = 1e-3;
  const auto hit = intersect_shape(s, Ray{Vec3::Zero(), Vec3(0, 0, -1)}, INFINITY);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 1e6 - 1e-3, 1e-7);
}

}  // namespace
}  // namespace mbk
