// A texel's position-normal element bounds in normal space (see element_normal_bounds.h).
#include "libbake/glint/element_normal_bounds.h"

#include <cmath>

#include "libbake/glint/example_jacobian.h"
#include "libbake/glint/glint_technique.h"

namespace mbk {

RmqBounds element_normal_bounds(const NormalMap& example, uint32_t x, uint32_t row) {
  const Mat2 j = example_jacobian(example, x, row);
  constexpr double kReach = kGlintSpatialCutoffSigmas * kGlintElementSigmaTexels;  // 3 sigma_h, in texels
  const double rx = (std::abs(j(0, 0)) + std::abs(j(0, 1))) * kReach;
  const double ry = (std::abs(j(1, 0)) + std::abs(j(1, 1))) * kReach;
  const Vec3f& n = example.at(x, row);
  return {double(n.x()) - rx, double(n.x()) + rx, double(n.y()) - ry, double(n.y()) + ry};
}

}  // namespace mbk
