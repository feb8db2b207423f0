// Direct lighting from point/directional lights and SH distant lighting (see scene_lighting.h).
#include "libbake/eval/scene_lighting.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "libbake/eval/distant_radiance.h"

namespace mbk {

SceneLighting load_scene_lighting(const Scene& scene) {
  SceneLighting out;
  out.points = scene.lights.points;
  out.directionals = scene.lights.directionals;
  LoadCache cache;
  const DistantRadiance distant = DistantRadiance::load(scene, cache);
  out.has_distant = !distant.empty();
  const std::vector<Vec3> sh = distant.sh(2);
  std::copy(sh.begin(), sh.end(), out.distant.begin());
  return out;
}

Vec3 facing_viewer(const Vec3& n, const Vec3& v) {
  const double c = n.dot(v);
  return c >= kMinCosView ? n : Vec3((n + (kMinCosView - c) * v).normalized());  // n' . v = 0.01 / |n'| > 0
}

void for_each_direct_light(const SceneLighting& lighting, const Vec3& position, const Vec3& geometric_normal,
                           const std::function<void(const Vec3& l, const Vec3& e, double distance)>& light) {
  const auto visit = [&](const Vec3& l, const Vec3& e, double distance) {
    if (geometric_normal.dot(l) > 0.0) light(l, e, distance);  // else below the surface's own horizon
  };
  for (const auto& p : lighting.points) {
    const Vec3 to_light = p.position - position;
    const double d2 = to_light.squaredNorm();
    if (!(d2 > 0.0)) continue;  // a light exactly on the surface has no direction
    const double d = std::sqrt(d2);
    visit(to_light / d, p.intensity / d2, d);
  }
  for (const auto& d : lighting.directionals)
    visit(-d.direction, d.irradiance, std::numeric_limits<double>::infinity());
}

Vec3 distant_specular(const SceneLighting& lighting, const Vec3& f0, const Vec3& n, const Vec3& v, double alpha) {
  if (!lighting.has_distant) return Vec3::Zero();
  const double cos_v = n.dot(v);
  const Vec3 mirror = 2.0 * cos_v * n - v;
  return schlick_fresnel(f0, cos_v).cwiseProduct(
      sh_lobe_radiance(lighting.distant, mirror, specular_lobe_kappa(alpha)));
}

Vec3 shade(const SceneLighting& lighting, const Brdf& brdf, const ShadingPoint& point) {
  const Vec3 n = facing_viewer(point.normal, point.to_viewer);
  Vec3 radiance = Vec3::Zero();
  for_each_direct_light(lighting, point.position, point.geometric_normal, [&](const Vec3& l, const Vec3& e, double) {
    const double cos_l = n.dot(l);
    if (cos_l > 0.0) radiance += evaluate_brdf(brdf, n, l, point.to_viewer).cwiseProduct(e) * cos_l;
  });
  return radiance + shade_distant(lighting, brdf, n, point.to_viewer, brdf.lobe.alpha);
}

Vec3 shade_distant(const SceneLighting& lighting, const Brdf& brdf, const Vec3& n, const Vec3& v, double alpha) {
  if (!lighting.has_distant) return Vec3::Zero();
  return brdf.albedo.cwiseProduct(sh_irradiance(lighting.distant, n)) / std::numbers::pi +
         distant_specular(lighting, brdf.f0, n, v, alpha);
}

Vec3 background(const SceneLighting& lighting, const Vec3& direction) {
  return lighting.has_distant ? sh_radiance(lighting.distant, direction) : Vec3::Zero();
}

}  // namespace mbk
