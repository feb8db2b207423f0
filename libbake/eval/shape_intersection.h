// Ray casting of the scene's shapes, returning what shading needs: the hit point, the geometric normal,
// the texture coordinates uv (already multiplied by the shape's uv_scale) and the partial derivatives
// dp/du, dp/dv of the surface with respect to those uv (so that texel footprints come out in the map's
// units). Every shape's parameterisation has dp/du x dp/dv along the outward normal, matching the tangent
// space of libbake/image/normal_map.h (x = +u, y = +v, z = out). With the shape frame (T = tangent,
// N = normal, B = N x T) and s = uv_scale:
//
// plane      p = c + (u' - 1/2) w T + (v' - 1/2) h B,  u' = u/s_u, v' = v/s_v in [0, 1]
//            dp/du = (w / s_u) T,  dp/dv = (h / s_v) B.
// sphere     p = c + r q,  q = sin(th) cos(ph) T + sin(th) sin(ph) B + cos(th) N,  N is the pole,
//            u' = ph / 2pi (ph in [0, 2pi), measured from T towards B), v' = 1 - th / pi (v' = 1 at the pole N)
//            dp/du = (2pi r / s_u) sin(th) (-sin(ph) T + cos(ph) B)
//            dp/dv = (pi r / s_v) (-cos(th) cos(ph) T - cos(th) sin(ph) B + sin(th) N)
//            dp/du vanishes at the poles; shading picks a tangent there (see surface_frame.h).
// bent_quad  the plane's rectangle bent around an axis parallel to B into a cylindrical arc of angle a
//            (signed; arc length w is kept, so the radius is R = w / a, negative = bent towards N):
//            ph = (u' - 1/2) a,  p = c + R sin(ph) T + R (cos(ph) - 1) N + (v' - 1/2) h B,
//            normal = sin(ph) T + cos(ph) N,  dp/du = (w / s_u)(cos(ph) T - sin(ph) N),  dp/dv = (h / s_v) B.
#pragma once

#include <optional>
#include <vector>

#include "libbake/eval/camera_rays.h"
#include "libbake/scene/scene.h"

namespace mbk {

struct SurfaceHit {
  double t = 0;
  Vec3 p;
  Vec3 normal;  // unit, outward (along dp/du x dp/dv), not yet turned towards the viewer
  Vec2 uv;
  Vec3 dpdu, dpdv;
  size_t shape = 0;  // index in Scene::shapes
};

// The nearest hit with t in (0, t_max), if any. The direction must be unit length.
std::optional<SurfaceHit> intersect_shape(const Shape& shape, const Ray& ray, double t_max);
std::optional<SurfaceHit> intersect_scene(const std::vector<Shape>& shapes, const Ray& ray);

}  // namespace mbk
