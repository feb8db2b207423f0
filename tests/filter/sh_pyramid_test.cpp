// SH NDF pyramids (libbake/filter/sh_pyramid.h, [Han07] Sec. 7.4.1): every coarse texel equals the brute-force
// area-weighted mean of Y_lm over the finest normals it covers (odd, degenerate and power-of-two sizes);
// a 2x2 block is the mean of its four deltas; results do not depend on the thread count; order 128 is finite.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/mip_levels.h"
#include "libbake/core/parallel.h"
#include "libbake/core/sh_basis.h"
#include "libbake/filter/sh_pyramid.h"
#include "tests/filter/filter_test_maps.h"

namespace mbk {
namespace {

// Brute force: for each level texel, the weighted sum over every finest texel of its coverage fraction (the
// product of its overlaps along x and y, computed here from the interval rule) times Y(n).
std::vector<double> brute_force_level(const NormalMap& map, int order, uint32_t w, uint32_t h) {
  const ShBasisEvaluator basis(order);
  const int count = basis.count();
  std::vector<double> out(size_t(w) * h * count, 0.0);
  auto overlap = [](uint32_t i, uint32_t n, uint32_t x, uint32_t extent) {
    // texel i of n covers [i extent / n, (i+1) extent / n) in finest units; finest x covers [x, x + 1)
    const double lo = std::max(double(i) * extent / n, double(x)), hi = std::min(double(i + 1) * extent / n, x + 1.0);
    return std::max(0.0, hi - lo) * n / extent;
  };
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i)
      for (uint32_t y = 0; y < map.height; ++y)
        for (uint32_t x = 0; x < map.width; ++x) {
          const double weight = overlap(i, w, x, map.width) * overlap(j, h, y, map.height);
          if (weight == 0.0) continue;
          const auto v = basis.evaluate(map.at(x, y).cast<double>());
          for (int k = 0; k < count; ++k) out[(size_t(j) * w + i) * count + k] += weight * v[size_t(k)];
        }
  return out;
}

class ShPyramidSizes : public ::testing::TestWithParam<std::pair<uint32_t, uint32_t>> {};

TEST_P(ShPyramidSizes, CoefficientsAreMeansOfBasisOverCoveredNormals) {
  const auto [W, H] = GetParam();
  constexpr int kOrder = 6;
  const NormalMap map = test::random_normal_map(W, H, W * 100 + H);
  const ShPyramid p = build_sh_pyramid(map, kOrder, Progress::silent());
  const auto sizes = mip_level_sizes(W, H);
  ASSERT_EQ(p.levels.size(), sizes.size() - 1);
  for (size_t k = 1; k < sizes.size(); ++k) {
    const ShLevel& level = p.levels[k - 1];
    ASSERT_EQ(level.width, sizes[k].width);
    ASSERT_EQ(level.height, sizes[k].height);
    const auto expected = brute_force_level(map, kOrder, level.width, level.height);
    ASSERT_EQ(level.coefficients.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i)
      ASSERT_NEAR(level.coefficients[i], expected[i], 2e-6) << "level " << k << " element " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(OddDegenerateAndPowerOfTwo, ShPyramidSizes,
                         ::testing::Values(std::pair{16u, 16u}, std::pair{7u, 5u}, std::pair{13u, 9u},
                                           std::pair{1u, 6u}, std::pair{10u, 3u}, std::pair{12u, 12u},
                                           std::pair{1u, 1u}));

// At a realistic size the first levels are built in one pass from the normals, a level's rows from the finer ones
// of the same group (stream_sh_pyramid's chain: at 1024 x 576 levels 1..3, then level 4 from level 3): every texel
// of levels 1..6, where 2^k divides both sides, is the mean of Y_lm over its 2^k x 2^k block of normals,
// accumulated here in double from the basis values of the finest texels.
TEST(ShPyramid, ChainOfNestedLevelsIsTheBlockMeanAtRealisticSize) {
  constexpr uint32_t W = 1024, H = 576;
  constexpr int kOrder = 4;
  const NormalMap map = test::random_normal_map(W, H, 77);
  const ShPyramid p = build_sh_pyramid(map, kOrder, Progress::silent());
  const ShBasisEvaluator basis(kOrder);
  const size_t count = size_t(basis.count());
  std::vector<double> y(size_t(W) * H * count);
  for (size_t t = 0; t < map.texels.size(); ++t) {
    const auto v = basis.evaluate(map.texels[t].cast<double>());
    std::copy(v.begin(), v.end(), y.begin() + t * count);
  }
  for (uint32_t k = 1; k <= 6; ++k) {
    const ShLevel& level = p.levels[k - 1];
    const uint32_t side = 1u << k;
    ASSERT_EQ(level.width, W / side);
    ASSERT_EQ(level.height, H / side);
    for (uint32_t j = 0; j < level.height; ++j)
      for (uint32_t i = 0; i < level.width; ++i)
        for (size_t c = 0; c < count; ++c) {
          double sum = 0.0;
          for (uint32_t yy = j * side; yy < (j + 1) * side; ++yy)
            for (uint32_t xx = i * side; xx < (i + 1) * side; ++xx) sum += y[(size_t(yy) * W + xx) * count + c];
          ASSERT_NEAR(level.texel(i, j, int(count))[c], sum / double(side * side), 2e-6)
              << "level " << k << " texel (" << i << ", " << j << ") coefficient " << c;
        }
  }
}

TEST(ShPyramid, TwoByTwoBlockIsMeanOfFourDeltas) {
  const NormalMap map = test::random_normal_map(2, 2, 5);
  const ShPyramid p = build_sh_pyramid(map, 4, Progress::silent());
  ASSERT_EQ(p.levels.size(), 1u);
  const ShBasisEvaluator basis(4);
  std::vector<double> mean(size_t(basis.count()), 0.0);
  for (const Vec3f& n : map.texels) {
    const auto y = basis.evaluate(n.cast<double>());
    for (size_t k = 0; k < mean.size(); ++k) mean[k] += 0.25 * y[k];
  }
  for (size_t k = 0; k < mean.size(); ++k) EXPECT_NEAR(p.levels[0].coefficients[k], mean[k], 1e-7);
}

TEST(ShPyramid, SameResultWhateverTheThreadCount) {
  const NormalMap map = test::random_normal_map(37, 23, 9);
  set_thread_count(1);
  const ShPyramid one = build_sh_pyramid(map, 5, Progress::silent());
  set_thread_count(2);
  const ShPyramid two = build_sh_pyramid(map, 5, Progress::silent());
  set_thread_count(0);
  ASSERT_EQ(one.levels.size(), two.levels.size());
  for (size_t k = 0; k < one.levels.size(); ++k) EXPECT_EQ(one.levels[k].coefficients, two.levels[k].coefficients);
}

TEST(ShPyramid, Order128FiniteAtHorizonAndPoleNormals) {
  NormalMap map;
  map.width = 2, map.height = 2;
  map.texels = {Vec3f(0, 0, 1), Vec3f(1, 0, 0), Vec3f(0, -1, 0), Vec3f(0.6f, 0.0f, 0.8f)};
  const ShPyramid p = build_sh_pyramid(map, 128, Progress::silent());
  for (float v : p.levels[0].coefficients) ASSERT_TRUE(std::isfinite(v));
  EXPECT_NEAR(p.levels[0].coefficients[0], 0.5 / std::sqrt(3.14159265358979), 1e-7);
}

}  // namespace
}  // namespace mbk
