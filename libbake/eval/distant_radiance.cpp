// Distant radiance by direction and its SH projection (see distant_radiance.h).
#include "libbake/eval/distant_radiance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "libbake/eval/sh_lighting.h"

namespace mbk {

DistantRadiance DistantRadiance::load(const Scene& scene, LoadCache& cache) {
  DistantRadiance out;
  for (const EnvironmentLight& env : scene.lights.environments)
    out.maps_.push_back(
        {cache.get<Image>("environment|" + env.path.string(), [&] { return load_image(env.path); }), env.scale});
  for (const SkyLight& sky : scene.lights.skies) {
    out.sky_ += sky.radiance;
    out.has_sky_ = true;
  }
  return out;
}

Vec3 DistantRadiance::radiance(const Vec3& d) const {
  Vec3 sum = sky_;
  if (maps_.empty()) return sum;
  const Vec2 angles = lat_long_angles(d);
  const double phi = angles.x(), theta = angles.y();
  for (const Map& m : maps_) {
    const Image& im = *m.image;
    const uint32_t i = std::min(uint32_t(phi / (2.0 * std::numbers::pi) * im.width), im.width - 1);
    const uint32_t row = std::min(uint32_t(theta / std::numbers::pi * im.height), im.height - 1);
    Vec3 l;
    for (uint32_t c = 0; c < 3; ++c) l[c] = im.at(i, row, im.channels >= 3 ? c : 0);
    sum += m.scale * l;
  }
  return sum;
}

std::vector<Vec3> DistantRadiance::sh(int order) const {
  std::vector<Vec3> out(size_t((order + 1) * (order + 1)), Vec3::Zero());
  for (const Map& m : maps_) {
    const std::vector<Vec3> p = project_lat_long(*m.image, order);
    for (size_t k = 0; k < out.size(); ++k) out[k] += m.scale * p[k];
  }
  if (has_sky_) out[0] += constant_radiance_sh(sky_)[0];
  return out;
}

}  // namespace mbk
