// The scene's distant lighting as a function of direction, unprojected: each environment map piecewise constant
// over its texels (the very function sh_lighting.h projects, so an SH projection of any order converges to it)
// times its scale, plus every uniform sky. Shaders that need more than the order-2 lighting of scene_lighting.h read
// it: the histogram effect's reference integrates it by Monte Carlo, and its filtered shader dots a projection of
// order L (sh(order)) with the footprint's NDF ([Shah24] Eq. 9).
#pragma once

#include <memory>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/eval/load_cache.h"
#include "libbake/image/image_io.h"
#include "libbake/scene/scene.h"

namespace mbk {

class DistantRadiance {
 public:
  // Loads the scene's environment maps through `cache` (Error from image_io when one cannot be read).
  static DistantRadiance load(const Scene& scene, LoadCache& cache);
  bool empty() const { return maps_.empty() && !has_sky_; }
  // Radiance arriving from the unit direction d (lat-long conventions of sh_lighting.h), linear RGB.
  Vec3 radiance(const Vec3& d) const;
  // Its SH coefficients to order L: (L + 1)^2 RGB values.
  std::vector<Vec3> sh(int order) const;

 private:
  struct Map {
    std::shared_ptr<const Image> image;
    double scale = 1;
  };
  std::vector<Map> maps_;
  Vec3 sky_ = Vec3::Zero();
  bool has_sky_ = false;
};

}  // namespace mbk
