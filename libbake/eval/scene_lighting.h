// How the scene's lights shade a surface point: point and directional lights through the full BRDF
// (microfacet_brdf.h), and all distant lighting (environment maps times their scale, plus uniform skies)
// summed into one set of order-2 SH coefficients (sh_lighting.h: exact diffuse convolution, vMF specular
// approximation).
//
// No shadows: nothing occludes a light but the surface's own horizon; a point or directional light
// contributes only where it is above the geometric surface (n_g . l > 0) and above the shading normal
// (n . l > 0). A shading normal that faces away from the viewer (n . v < 0.01, common with normal maps at
// grazing angles) is bent towards the viewer first, n <- normalize(n + (0.01 - n . v) v), so that
// n . v > 0: otherwise such points would reflect nothing and sprinkle black texels over the image (the
// reference, whose unfiltered normals do this most, gets the same treatment). Rays that miss every shape
// see the SH radiance of the distant lighting (black without it).
#pragma once

#include <functional>
#include <vector>

#include "libbake/eval/microfacet_brdf.h"
#include "libbake/eval/sh_lighting.h"
#include "libbake/scene/scene.h"

namespace mbk {

struct SceneLighting {
  std::vector<PointLight> points;
  std::vector<DirectionalLight> directionals;
  bool has_distant = false;  // any environment or sky
  ShCoefficients distant{};
};

// Loads and projects the environment maps (Error from image_io when one cannot be read).
SceneLighting load_scene_lighting(const Scene& scene);

struct ShadingPoint {
  Vec3 position;
  Vec3 geometric_normal;  // unit, turned towards the viewer
  Vec3 normal;            // unit shading normal
  Vec3 to_viewer;         // unit
};

// The shading normal actually used: `normal`, bent towards the viewer when n . v < kMinCosView (see above).
inline constexpr double kMinCosView = 0.01;
Vec3 facing_viewer(const Vec3& normal, const Vec3& to_viewer);
// Calls light(l, e, distance) for every point and directional light above the geometric horizon at `position`
// (n_g . l > 0): l the unit direction towards the light, e its irradiance on a surface facing it, distance
// the light's (infinity for a directional light). The shading normal's horizon is the caller's (shade() and
// the filtered-NDF shaders test it their way).
void for_each_direct_light(const SceneLighting& lighting, const Vec3& position, const Vec3& geometric_normal,
                           const std::function<void(const Vec3& l, const Vec3& e, double distance)>& light);
// The distant lighting's specular around the unit normal n (already facing the viewer) for microfacet
// roughness alpha: F_Schlick(f0, n.v) times the vMF lobe of kappa = 1 / (2 alpha^2) at the mirror direction
// (sh_lighting.h). Zero without distant lights.
Vec3 distant_specular(const SceneLighting& lighting, const Vec3& f0, const Vec3& n, const Vec3& v, double alpha);
// Radiance towards the viewer, linear RGB.
Vec3 shade(const SceneLighting& lighting, const Brdf& brdf, const ShadingPoint& point);
// Its distant-lighting part around the unit normal n (already facing the viewer), with the specular lobe's alpha:
// the diffuse irradiance and distant_specular (zero without distant lights).
Vec3 shade_distant(const SceneLighting& lighting, const Brdf& brdf, const Vec3& n, const Vec3& v, double alpha);
// What a ray that hits nothing sees.
Vec3 background(const SceneLighting& lighting, const Vec3& direction);

}  // namespace mbk
