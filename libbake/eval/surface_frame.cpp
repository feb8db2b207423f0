// Tangent frames at hits (see surface_frame.h).
#include "libbake/eval/surface_frame.h"

#include <Eigen/Geometry>  // cross products

namespace mbk {

SurfaceFrame surface_frame(const SurfaceHit& hit, const Vec3& to_viewer) {
  SurfaceFrame f;
  f.N = hit.normal;
  Vec3 t = hit.dpdu - hit.dpdu.dot(f.N) * f.N;
  // |dp/du| relative to |dp/dv| below 1e-9: within a nanoradian of a sphere's pole, where dp/du's direction
  // is rounding noise.
  if (t.norm() <= 1e-9 * hit.dpdv.norm()) t = hit.dpdv.cross(f.N);
  f.T = t.normalized();
  f.B = f.N.cross(f.T);
  if (f.N.dot(to_viewer) < 0.0) {
    f.N = -f.N;
    f.B = -f.B;
  }
  return f;
}

}  // namespace mbk
