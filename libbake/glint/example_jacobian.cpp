// Central / one-sided differences of an example's normal components (see example_jacobian.h).
#include "libbake/glint/example_jacobian.h"

namespace mbk {
namespace {

// d(n_x, n_y) along one axis at index i of n texels; `at(j)` reads the normal at index j on that axis.
template <typename At>
Vec2 axis_difference(uint32_t i, uint32_t n, At at) {
  if (n == 1) return Vec2::Zero();
  const uint32_t before = i == 0 ? 0 : i - 1, after = i + 1 == n ? i : i + 1;
  const Vec3 d = at(after).template cast<double>() - at(before).template cast<double>();
  return Vec2(d.x(), d.y()) / double(after - before);
}

}  // namespace

Mat2 example_jacobian(const NormalMap& example, uint32_t x, uint32_t row) {
  Mat2 j;
  j.col(0) = axis_difference(x, example.width, [&](uint32_t i) { return example.at(i, row); });
  j.col(1) = axis_difference(row, example.height, [&](uint32_t i) { return example.at(x, i); });
  return j;
}

}  // namespace mbk
