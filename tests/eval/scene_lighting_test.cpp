// Shading a point: point lights fall off as intensity / d^2 times the cosine, directional lights give
// irradiance times the cosine, a uniform sky gives albedo * L plus F(n.v) * L, lights below the surface's
// own horizon add nothing, and a shading normal facing away from the viewer is bent towards it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libbake/eval/scene_lighting.h"

namespace mbk {
namespace {

const Brdf kBrdf{Vec3(0.6, 0.5, 0.4), Vec3::Constant(0.04), {Distribution::ggx, 0.4}};

ShadingPoint flat_point(const Vec3& to_viewer) {
  return {Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitZ(), to_viewer.normalized()};
}

TEST(SceneLighting, PointLightFallsOffWithDistanceSquaredTimesCosine) {
  SceneLighting lighting;
  lighting.points = {{Vec3(1.0, 0.0, 2.0), Vec3(5.0, 4.0, 3.0)}};
  const ShadingPoint p = flat_point(Vec3(-0.3, 0.2, 1.0));
  const Vec3 l = Vec3(1.0, 0.0, 2.0).normalized();
  const Vec3 expected = evaluate_brdf(kBrdf, p.normal, l, p.to_viewer).cwiseProduct(Vec3(5.0, 4.0, 3.0)) / 5.0 * l.z();
  EXPECT_LT((shade(lighting, kBrdf, p) - expected).norm(), 1e-14);
  EXPECT_GT(expected.minCoeff(), 0.0);
}

TEST(SceneLighting, DirectionalLightGivesIrradianceTimesCosine) {
  SceneLighting lighting;
  lighting.directionals = {{Vec3(0.0, -0.6, -0.8), Vec3(2.0, 2.0, 2.0)}};  // travelling down and away
  const ShadingPoint p = flat_point(Vec3(0.1, 0.0, 1.0));
  const Vec3 l(0.0, 0.6, 0.8);
  const Vec3 expected = evaluate_brdf(kBrdf, p.normal, l, p.to_viewer) * 2.0 * 0.8;
  EXPECT_LT((shade(lighting, kBrdf, p) - expected).norm(), 1e-14);
}

TEST(SceneLighting, UniformSkyGivesAlbedoTimesRadiancePlusFresnelReflection) {
  SceneLighting lighting;
  lighting.has_distant = true;
  lighting.distant = constant_radiance_sh(Vec3(0.2, 0.3, 0.4));
  const ShadingPoint p = flat_point(Vec3(0.5, 0.0, 1.0));
  const Vec3 L(0.2, 0.3, 0.4);
  const Vec3 expected = kBrdf.albedo.cwiseProduct(L) + schlick_fresnel(kBrdf.f0, p.to_viewer.z()).cwiseProduct(L);
  EXPECT_LT((shade(lighting, kBrdf, p) - expected).norm(), 1e-14);
  EXPECT_LT((background(lighting, Vec3(0.0, -1.0, 0.0)) - L).norm(), 1e-14);
  EXPECT_EQ(background(SceneLighting{}, Vec3::UnitX()), Vec3::Zero());
}

TEST(SceneLighting, LightsBelowTheGeometricHorizonAddNothing) {
  SceneLighting lighting;
  lighting.points = {{Vec3(1.0, 0.0, -0.1), Vec3::Ones()}};
  lighting.directionals = {{Vec3(0.0, 0.0, 1.0), Vec3::Ones()}};  // travelling up: from below
  ShadingPoint p = flat_point(Vec3(0.0, 0.0, 1.0));
  // Even a shading normal tilted towards the light does not let it through the surface.
  p.normal = Vec3(0.8, 0.0, 0.6);
  EXPECT_EQ(shade(lighting, kBrdf, p), Vec3::Zero());
}

TEST(SceneLighting, NormalsFacingAwayFromTheViewerAreBentTowardsIt) {
  const Vec3 v = Vec3(1.0, 0.0, 0.2).normalized();
  const Vec3 n = Vec3(-0.6, 0.0, 0.8);
  const Vec3 bent = facing_viewer(n, v);
  EXPECT_NEAR(bent.norm(), 1.0, 1e-15);
  EXPECT_GT(bent.dot(v), 0.0);
  // n + (0.01 - c) v has n'.v = 0.01 and length sqrt(1 + 0.01^2 - c^2), c = n.v: bent just enough.
  const double c = n.dot(v);
  EXPECT_NEAR(bent.dot(v), 0.01 / std::sqrt(1 + 1e-4 - c * c), 1e-15);
  EXPECT_GT(bent.z(), 0.0);                                   // still above the surface
  EXPECT_EQ(facing_viewer(Vec3::UnitZ(), v), Vec3::UnitZ());  // a visible normal is kept as it is
  SceneLighting lighting;
  lighting.has_distant = true;
  lighting.distant = constant_radiance_sh(Vec3::Ones());
  ShadingPoint p = flat_point(v);
  p.normal = n;
  EXPECT_GT(shade(lighting, kBrdf, p).minCoeff(), 0.0);  // not black
}

}  // namespace
}  // namespace mbk
