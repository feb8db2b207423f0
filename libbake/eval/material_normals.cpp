// Normal lookups: trilinear in a MIP pyramid, or bilinear in the raw map (see material_normals.h).
#include "libbake/eval/material_normals.h"

namespace mbk {

Vec3 MaterialNormals::lookup(const Vec2& uv, const UvFootprint& footprint) const {
  if (filter == NormalFilter::none) return Vec3::UnitZ();
  const NormalMap& finest = pyramid->levels[0];
  const Vec3 n = filter == NormalFilter::bilinear_level0
                     ? sample_bilinear(finest, uv)
                     : sample_pyramid(*pyramid, uv, mip_lod(footprint, finest.width, finest.height));
  const double len = n.norm();
  // Means of unit vectors shorter than this have lost their direction to cancellation (and float rounding
  // of the stored levels is ~1e-7): fall back to the unperturbed normal.
  return len > 1e-6 ? Vec3(n / len) : Vec3::UnitZ();
}

}  // namespace mbk
