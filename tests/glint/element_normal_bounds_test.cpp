// The leaf intervals of the RMQ table (element_normal_bounds.h): each texel's interval holds every one of its
// sub-elements - the bilinear example linearized at the texel's quarter points - over the sub-element cut-off
// square, on random maps including their borders and one-texel axes; on a linear map (where the bilinear field
// is the linear one) the interval is exactly the reach of the largest sub-element; a constant map gives points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "libbake/glint/element_normal_bounds.h"
#include "libbake/glint/example_bilinear.h"
#include "libbake/glint/glint_technique.h"

namespace mbk {
namespace {

NormalMap random_map(uint32_t w, uint32_t h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> v(-0.6f, 0.6f);
  NormalMap m;
  m.width = w, m.height = h;
  for (size_t i = 0; i < size_t(w) * h; ++i) m.texels.emplace_back(v(rng), v(rng), 0.5f);
  return m;
}

// The range of sub-element q of texel (x, row) over its cut-off square, by a 21 x 21 grid of its corners and
// inside (a linear function's extremes over a square are at its corners, which the grid contains).
RmqBounds sub_element_range(const ExampleChannels& e, uint32_t x, uint32_t row, int a0, int a1) {
  constexpr int kK = kGlintSubElementsPerAxis;
  const Vec2 u(x + (a0 + 0.5) / kK, row + (a1 + 0.5) / kK);
  const NormalSample q = sample_example_bilinear(e, u);
  const double reach = kGlintSpatialCutoffSigmas * kGlintSubElementSigmaTexels;
  RmqBounds b{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (int i = 0; i <= 20; ++i)
    for (int k = 0; k <= 20; ++k) {
      const Vec2 n = q.n + q.jacobian * Vec2(reach * (i / 10.0 - 1.0), reach * (k / 10.0 - 1.0));
      b = {std::min(b.min_x, n.x()), std::max(b.max_x, n.x()), std::min(b.min_y, n.y()), std::max(b.max_y, n.y())};
    }
  return b;
}

TEST(ElementNormalBounds, ContainsEverySubElement) {
  for (const auto& [w, h] : {std::pair{9u, 7u}, std::pair{1u, 6u}, std::pair{5u, 1u}, std::pair{1u, 1u}}) {
    const NormalMap m = random_map(w, h, w * 31 + h);
    const ExampleChannels e = normal_components(m);
    for (uint32_t row = 0; row < h; ++row)
      for (uint32_t x = 0; x < w; ++x) {
        const RmqBounds leaf = element_normal_bounds(m, x, row);
        for (int a1 = 0; a1 < kGlintSubElementsPerAxis; ++a1)
          for (int a0 = 0; a0 < kGlintSubElementsPerAxis; ++a0) {
            const RmqBounds q = sub_element_range(e, x, row, a0, a1);
            EXPECT_LE(leaf.min_x, q.min_x + 1e-12) << w << "x" << h << " texel " << x << "," << row;
            EXPECT_GE(leaf.max_x, q.max_x - 1e-12) << w << "x" << h << " texel " << x << "," << row;
            EXPECT_LE(leaf.min_y, q.min_y + 1e-12) << w << "x" << h << " texel " << x << "," << row;
            EXPECT_GE(leaf.max_y, q.max_y - 1e-12) << w << "x" << h << " texel " << x << "," << row;
          }
      }
  }
}

TEST(ElementNormalBounds, LinearMapReachesExactlyTheLargestSubElement) {
  // n_x = 0.01 x - 0.02 row, n_y = 0.005 row (exact in float at these sizes to ~1e-8).
  NormalMap m;
  m.width = 8, m.height = 6;
  for (uint32_t row = 0; row < 6; ++row)
    for (uint32_t x = 0; x < 8; ++x) m.texels.emplace_back(float(0.01 * x - 0.02 * row), float(0.005 * row), 0.5f);
  const ExampleChannels e = normal_components(m);
  for (uint32_t row = 1; row < 5; ++row)
    for (uint32_t x = 1; x < 7; ++x) {
      const RmqBounds leaf = element_normal_bounds(m, x, row);
      RmqBounds all{INFINITY, -INFINITY, INFINITY, -INFINITY};
      for (int a1 = 0; a1 < kGlintSubElementsPerAxis; ++a1)
        for (int a0 = 0; a0 < kGlintSubElementsPerAxis; ++a0) {
          const RmqBounds q = sub_element_range(e, x, row, a0, a1);
          all = {std::min(all.min_x, q.min_x), std::max(all.max_x, q.max_x), std::min(all.min_y, q.min_y),
                 std::max(all.max_y, q.max_y)};
        }
      EXPECT_NEAR(leaf.min_x, all.min_x, 1e-7);
      EXPECT_NEAR(leaf.max_x, all.max_x, 1e-7);
      EXPECT_NEAR(leaf.min_y, all.min_y, 1e-7);
      EXPECT_NEAR(leaf.max_y, all.max_y, 1e-7);
    }
}

TEST(ElementNormalBounds, RowReachIsTheTexelReachBitForBit) {
  // Random maps with one-texel axes and 2-texel sides (every border case of the 3 x 3 block), and a map whose
  // rows differ by exact steps (many ties between the maxima).
  std::vector<NormalMap> maps;
  for (const auto& [w, h] : {std::pair{37u, 23u}, std::pair{1u, 6u}, std::pair{5u, 1u}, std::pair{1u, 1u},
                             std::pair{2u, 2u}, std::pair{2u, 7u}})
    maps.push_back(random_map(w, h, w * 17 + h));
  NormalMap steps;
  steps.width = 9, steps.height = 5;
  for (uint32_t i = 0; i < 45; ++i) steps.texels.emplace_back(float(i % 3) * 0.25f, float(i % 4) * -0.125f, 0.5f);
  maps.push_back(steps);
  for (const NormalMap& m : maps)
    for (uint32_t row = 0; row < m.height; ++row) {
      std::vector<double> rx(m.width, -1.0), ry(m.width, -1.0);
      element_normal_reach_row(m, row, rx.data(), ry.data());
      for (uint32_t x = 0; x < m.width; ++x) {
        const Vec2 texel = element_normal_reach(m, x, row);
        EXPECT_EQ(rx[x], texel.x()) << m.width << "x" << m.height << " texel " << x << "," << row;
        EXPECT_EQ(ry[x], texel.y()) << m.width << "x" << m.height << " texel " << x << "," << row;
      }
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
