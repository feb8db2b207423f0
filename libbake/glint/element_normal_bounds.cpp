// A texel's position-normal element bounds in normal space (see element_normal_bounds.h).
#include "libbake/glint/element_normal_bounds.h"

#include <algorithm>
#include <cmath>

#include "libbake/glint/glint_technique.h"

namespace mbk {

Vec2 element_normal_reach(const NormalMap& example, uint32_t x, uint32_t row) {
  constexpr double kK = kGlintSubElementsPerAxis;
  constexpr double kReach = 0.5 - 0.5 / kK + kGlintSpatialCutoffSigmas * kGlintElementSigmaTexels / kK;  // texels
  const uint32_t x_lo = x == 0 ? 0 : x - 1, x_hi = std::min(x + 1, example.width - 1);
  const uint32_t r_lo = row == 0 ? 0 : row - 1, r_hi = std::min(row + 1, example.height - 1);
  // D^x, D^y per component (x: n_x, y: n_y), in double.
  double dx[2] = {0.0, 0.0}, dy[2] = {0.0, 0.0};
  const auto widen = [](double* d, const Vec3f& a, const Vec3f& b) {
    d[0] = std::max(d[0], std::abs(double(a.x()) - double(b.x())));
    d[1] = std::max(d[1], std::abs(double(a.y()) - double(b.y())));
  };
  for (uint32_t r = r_lo; r <= r_hi; ++r)
    for (uint32_t i = x_lo; i < x_hi; ++i) widen(dx, example.at(i + 1, r), example.at(i, r));
  for (uint32_t r = r_lo; r < r_hi; ++r)
    for (uint32_t i = x_lo; i <= x_hi; ++i) widen(dy, example.at(i, r + 1), example.at(i, r));
  return Vec2((dx[0] + dy[0]) * kReach, (dx[1] + dy[1]) * kReach);
}

RmqBounds element_normal_bounds(const Vec3f& n, const Vec2& reach) {
  return {double(n.x()) - reach.x(), double(n.x()) + reach.x(), double(n.y()) - reach.y(), double(n.y()) + reach.y()};
}

RmqBounds element_normal_bounds(const NormalMap& example, uint32_t x, uint32_t row) {
  return element_normal_bounds(example.at(x, row), element_normal_reach(example, x, row));
}

}  // namespace mbk
