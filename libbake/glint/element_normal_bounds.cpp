// A texel's position-normal element bounds in normal space (see element_normal_bounds.h).
#include "libbake/glint/element_normal_bounds.h"

#include <cmath>

#include "libbake/glint/example_jacobian.h"
#include "libbake/glint/glint_technique.h"

namespace mbk {

Vec2 element_normal_reach(const NormalMap& example, uint32_t x, uint32_t row) {
  const Mat2 j = example_jacobian(example, x, row);
  constexpr double kReach = kGlintSpatialCutoffSigmas * kGlintElementSigmaTexels;  // 3 sigma_h, in texels
  return Vec2((std::abs(j(0, 0)) + std::abs(j(0, 1))) * kReach, (std::abs(j(1, 0)) + std::abs(j(1, 1))) * kReach);
}

RmqBounds element_normal_bounds(const Vec3f& n, const Vec2& reach) {
  return {double(n.x()) - reach.x(), double(n.x()) + reach.x(), double(n.y()) - reach.y(), double(n.y()) + reach.y()};
}

RmqBounds element_normal_bounds(const NormalMap& example, uint32_t x, uint32_t row) {
  return element_normal_bounds(example.at(x, row), element_normal_reach(example, x, row));
}

}  // namespace mbk
