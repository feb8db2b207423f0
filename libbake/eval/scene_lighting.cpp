// Direct lighting from point/directional lights and SH distant lighting (see scene_lighting.h).
#include "libbake/eval/scene_lighting.h"

#include <numbers>

#include "libbake/image/image_io.h"

namespace mbk {

SceneLighting load_scene_lighting(const Scene& scene) {
  SceneLighting out;
  out.points = scene.lights.points;
  out.directionals = scene.lights.directionals;
  out.distant.fill(Vec3::Zero());
  for (const auto& env : scene.lights.environments) {
    const ShCoefficients sh = project_lat_long(load_image(env.path));
    for (int k = 0; k < kShCount; ++k) out.distant[k] += env.scale * sh[k];
    out.has_distant = true;
  }
  for (const auto& sky : scene.lights.skies) {
    const ShCoefficients sh = constant_radiance_sh(sky.radiance);
    for (int k = 0; k < kShCount; ++k) out.distant[k] += sh[k];
    out.has_distant = true;
  }
  return out;
}

namespace {

// One light arriving from unit direction l with irradiance e (on a surface facing it).
Vec3 direct(const Brdf& brdf, const ShadingPoint& s, const Vec3& l, const Vec3& e) {
  if (!(s.geometric_normal.dot(l) > 0.0)) return Vec3::Zero();  // below the surface's own horizon
  const double cos_l = s.normal.dot(l);
  if (!(cos_l > 0.0)) return Vec3::Zero();
  return evaluate_brdf(brdf, s.normal, l, s.to_viewer).cwiseProduct(e) * cos_l;
}

}  // namespace

Vec3 facing_viewer(const Vec3& n, const Vec3& v) {
  constexpr double kMinCosView = 0.01;
  const double c = n.dot(v);
  return c >= kMinCosView ? n : Vec3((n + (kMinCosView - c) * v).normalized());  // n' . v = 0.01 / |n'| > 0
}

Vec3 shade(const SceneLighting& lighting, const Brdf& brdf, const ShadingPoint& point) {
  ShadingPoint s = point;
  s.normal = facing_viewer(point.normal, point.to_viewer);
  const double cos_v = s.normal.dot(s.to_viewer);
  Vec3 radiance = Vec3::Zero();
  for (const auto& light : lighting.points) {
    const Vec3 to_light = light.position - s.position;
    const double d2 = to_light.squaredNorm();
    if (!(d2 > 0.0)) continue;  // a light exactly on the surface has no direction
    radiance += direct(brdf, s, to_light / std::sqrt(d2), light.intensity / d2);
  }
  for (const auto& light : lighting.directionals) radiance += direct(brdf, s, -light.direction, light.irradiance);
  if (lighting.has_distant) {
    radiance += brdf.albedo.cwiseProduct(sh_irradiance(lighting.distant, s.normal)) / std::numbers::pi;
    const Vec3 mirror = 2.0 * cos_v * s.normal - s.to_viewer;
    radiance += schlick_fresnel(brdf.f0, cos_v)
                    .cwiseProduct(sh_lobe_radiance(lighting.distant, mirror, specular_lobe_kappa(brdf.lobe.alpha)));
  }
  return radiance;
}

Vec3 background(const SceneLighting& lighting, const Vec3& direction) {
  return lighting.has_distant ? sh_radiance(lighting.distant, direction) : Vec3::Zero();
}

}  // namespace mbk
