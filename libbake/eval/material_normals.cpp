// Normal lookups: trilinear in a MIP pyramid, or bilinear in the raw map (see material_normals.h).
#include "libbake/eval/material_normals.h"

namespace mbk {

Vec3 MaterialNormals::lookup(const Vec2& uv, const UvFootprint& footprint) const {
  if (filter == NormalFilter::none) return Vec3::UnitZ();
  const NormalMap& finest = pyramid->levels[0];
  Vec3 n = Vec3::Zero();
  if (filter == NormalFilter::bilinear_level0) {
    n = sample_bilinear(finest, uv);
  } else {  // the mean normal over the footprint: the mean of its anisotropic probes' means
    const FootprintProbes probes = footprint_probes(uv, footprint, finest.width, finest.height);
    for (const FootprintProbe& p : probes) n += sample_pyramid(*pyramid, p.uv, p.lod);
    n /= probes.size();
  }
  const double len = n.norm();
  // Means of unit vectors shorter than this have lost their direction to cancellation (and float rounding
  // of the stored levels is ~1e-7): fall back to the unperturbed normal.
  return len > 1e-6 ? Vec3(n / len) : Vec3::UnitZ();
}

}  // namespace mbk
