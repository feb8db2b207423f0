// uv to the glint target plane, with the v flip (see glint_surface_mapping.h).
#include "libbake/glint/glint_surface_mapping.h"

#include <algorithm>
#include <cmath>

namespace mbk {

Vec2 glint_target_point(const Vec2& uv, uint32_t width, uint32_t height) {
  return Vec2(uv.x() * width, (1.0 - uv.y()) * height);
}

Mat2 glint_tangent_jacobian(const Mat2& target_jacobian, uint32_t width, uint32_t height) {
  Mat2 scale = Mat2::Zero();
  scale(0, 0) = width;
  scale(1, 1) = -double(height);
  return target_jacobian * scale;
}

GlintFootprint glint_probe_footprint(const Vec2& uv, double box_width, uint32_t width, uint32_t height) {
  // Non-finite (grazing) stays non-finite, for footprint_texels() to refuse.
  const double sigma =
      std::isfinite(box_width) ? std::max(box_width / std::sqrt(12.0), kGlintMinFootprintSigma) : box_width;
  return {glint_target_point(uv, width, height), sigma};
}

}  // namespace mbk
