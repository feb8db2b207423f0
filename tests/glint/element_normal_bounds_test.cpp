// The leaf intervals of the RMQ table: example Jacobians by central differences (exact on quadratics),
// one-sided at the borders and zero across a single texel; and each texel's interval is exactly the range
// of its linear position-normal element over the 3 sigma_h cut-off square (attained at the corners).
#include <gtest/gtest.h>

#include <cmath>

#include "libbake/glint/element_normal_bounds.h"
#include "libbake/glint/example_jacobian.h"

namespace mbk {
namespace {

// n_x = a x^2 + b row, n_y = c row^2 - d x row (z unused by glints): central differences are exact on
// quadratics, so the expected Jacobian is known in closed form everywhere, borders included.
constexpr double a = 0.003, b = -0.01, c = 0.002, d = 0.0015;
NormalMap quadratic_map(uint32_t w, uint32_t h) {
  NormalMap m;
  m.width = w, m.height = h;
  m.texels.resize(size_t(w) * h);
  for (uint32_t row = 0; row < h; ++row)
    for (uint32_t x = 0; x < w; ++x)
      m.at(x, row) = Vec3f(float(a * x * x + b * row), float(c * row * row - d * x * row), 0.5f);
  return m;
}

TEST(ExampleJacobian, CentralDifferencesInsideOneSidedAtTheBorders) {
  const uint32_t W = 9, H = 6;
  const NormalMap m = quadratic_map(W, H);
  for (uint32_t row = 0; row < H; ++row)
    for (uint32_t x = 0; x < W; ++x) {
      // d/dx of a x^2 by the stencil used at x: central 2 a x; forward a (x=0); backward a (2W - 3) at x = W-1.
      const double dxx = x == 0 ? a : x == W - 1 ? a * (2.0 * W - 3.0) : 2 * a * x;
      const double drow_yy = row == 0 ? c : row == H - 1 ? c * (2.0 * H - 3.0) : 2 * c * row;
      const double dx_y = -d * row;  // d(-d x row)/dx, exact for any stencil (linear in x)
      const double drow_y = -d * x;
      const Mat2 j = example_jacobian(m, x, row);
      const double tol = 1e-6;  // the map is stored in float
      EXPECT_NEAR(j(0, 0), dxx, tol) << x << "," << row;
      EXPECT_NEAR(j(0, 1), b, tol) << x << "," << row;
      EXPECT_NEAR(j(1, 0), dx_y, tol) << x << "," << row;
      EXPECT_NEAR(j(1, 1), drow_yy + drow_y, tol) << x << "," << row;
    }
}

TEST(ExampleJacobian, SingleTexelAxisHasZeroDerivative) {
  const NormalMap column = quadratic_map(1, 5), row = quadratic_map(5, 1), one = quadratic_map(1, 1);
  for (uint32_t i = 0; i < 5; ++i) {
    EXPECT_EQ(example_jacobian(column, 0, i).col(0), Vec2::Zero());
    EXPECT_EQ(example_jacobian(row, i, 0).col(1), Vec2::Zero());
  }
  EXPECT_EQ(example_jacobian(one, 0, 0), Mat2::Zero());
}

TEST(ElementNormalBounds, SpreadIsJacobianTimesCutoff) {
  const NormalMap m = quadratic_map(7, 5);
  const double reach = 3.0 * 1.5 / std::sqrt(12.0);  // 3 sigma_h, sigma_h = 1.5 / sqrt(12) texels
  for (uint32_t row = 0; row < 5; ++row)
    for (uint32_t x = 0; x < 7; ++x) {
      const Mat2 j = example_jacobian(m, x, row);
      const RmqBounds bounds = element_normal_bounds(m, x, row);
      const double nx = m.at(x, row).x(), ny = m.at(x, row).y();
      const double rx = (std::abs(j(0, 0)) + std::abs(j(0, 1))) * reach;
      const double ry = (std::abs(j(1, 0)) + std::abs(j(1, 1))) * reach;
      EXPECT_DOUBLE_EQ(bounds.min_x, nx - rx);
      EXPECT_DOUBLE_EQ(bounds.max_x, nx + rx);
      EXPECT_DOUBLE_EQ(bounds.min_y, ny - ry);
      EXPECT_DOUBLE_EQ(bounds.max_y, ny + ry);
      // The linear element n + J (u - u_i) over the cut-off square stays inside and reaches both ends.
      double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
      for (int i = 0; i <= 20; ++i)
        for (int k = 0; k <= 20; ++k) {
          const Vec2 u(reach * (i / 10.0 - 1.0), reach * (k / 10.0 - 1.0));
          const Vec2 n = Vec2(nx, ny) + j * u;
          lo_x = std::min(lo_x, n.x()), hi_x = std::max(hi_x, n.x());
          lo_y = std::min(lo_y, n.y()), hi_y = std::max(hi_y, n.y());
        }
      EXPECT_NEAR(lo_x, bounds.min_x, 1e-12);
      EXPECT_NEAR(hi_x, bounds.max_x, 1e-12);
      EXPECT_NEAR(lo_y, bounds.min_y, 1e-12);
      EXPECT_NEAR(hi_y, bounds.max_y, 1e-12);
    }
}

TEST(ElementNormalBounds, ConstantMapHasPointIntervals) {
  NormalMap m;
  m.width = 4, m.height = 3;
  m.texels.assign(12, Vec3f(0.6f, -0.0f, 0.8f));
  for (uint32_t row = 0; row < 3; ++row)
    for (uint32_t x = 0; x < 4; ++x) {
      const RmqBounds b = element_normal_bounds(m, x, row);
      EXPECT_EQ(b.min_x, double(0.6f));
      EXPECT_EQ(b.max_x, double(0.6f));
      EXPECT_EQ(b.min_y, 0.0);
      EXPECT_EQ(b.max_y, 0.0);
    }
}

}  // namespace
}  // namespace mbk
