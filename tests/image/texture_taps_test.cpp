// box_taps (libbake/image/texture_taps.h) against brute force: each texel's weight is the fraction of a dense
// lattice of points in the box that falls in it (wrapping at the borders), for boxes narrower and wider than a
// texel, off the texel grid and on it, and wider than the whole level (folded: one tap per texel, so a box
// thousands of levels wide still has one tap per texel of the level); the weights sum to 1.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <map>
#include <utility>

#include "libbake/image/texture_taps.h"

namespace mbk {
namespace {

TEST(TextureTaps, BoxTapsWeighTexelsByTheirOverlapWithTheBox) {
  constexpr uint32_t kWidth = 8, kHeight = 6;
  constexpr int kLattice = 400;  // lattice points per box side: weights within ~2 / kLattice of the exact overlap
  struct Box {
    Vec2 uv;
    double half_x, half_y;
  };
  const Box boxes[] = {{{0.37, 0.61}, 0.3, 0.2},   {{0.5, 0.5}, 2.0, 1.5},     {{0.02, 0.97}, 1.7, 2.3},
                       {{0.0625, 0.25}, 0.5, 0.5}, {{0.81, 0.13}, 3.25, 0.75}, {{0.44, 0.52}, 5.5, 4.2},
                       {{-3.9, 12.25}, 1.05, 2.95}};
  for (const Box& box : boxes) {
    std::map<std::pair<uint32_t, uint32_t>, double> weights, brute;
    double sum = 0.0;
    const std::vector<TextureTap> taps = box_taps(kWidth, kHeight, box.uv, box.half_x, box.half_y);
    for (const TextureTap& tap : taps) {
      EXPECT_EQ(weights.count({tap.x, tap.row}), 0u) << "a texel met twice is one tap";
      weights[{tap.x, tap.row}] += tap.weight;
      sum += tap.weight;
    }
    EXPECT_LE(taps.size(),
              std::min(double(kWidth), 2 * box.half_x + 2) * std::min(double(kHeight), 2 * box.half_y + 2));
    EXPECT_NEAR(sum, 1.0, 1e-12);
    const Vec2 c = texel_coordinates(box.uv, kWidth, kHeight);
    for (int b = 0; b < kLattice; ++b)
      for (int a = 0; a < kLattice; ++a) {
        const double x = c.x() + box.half_x * (2.0 * (a + 0.5) / kLattice - 1.0);
        const double y = c.y() + box.half_y * (2.0 * (b + 0.5) / kLattice - 1.0);
        const auto wrap = [](double t, uint32_t n) { return uint32_t(t - n * std::floor(t / n)); };
        brute[{wrap(x, kWidth), wrap(y, kHeight)}] += 1.0 / (kLattice * kLattice);
      }
    for (const auto& [texel, weight] : brute)
      EXPECT_NEAR(weights[texel], weight, 4.0 / kLattice) << texel.first << "," << texel.second;
    for (const auto& [texel, weight] : weights) EXPECT_TRUE(brute.count(texel) || weight < 1e-12);
  }
}

TEST(TextureTaps, BoxThousandsOfLevelsWideIsOneTapPerTexelOfNearlyEqualWeight) {
  // 8000.6 x 2e6 texels over an 8 x 6 level: every texel is covered 1000 or 1001 times across, 333333 or 333334
  // down, so each weight is within a cover of 1 / 48 (a lattice would alias here, hence the closed form).
  const std::vector<TextureTap> taps = box_taps(8, 6, Vec2(0.3, 0.8), 4000.3, 1e6);
  ASSERT_EQ(taps.size(), 48u);
  double sum = 0.0;
  for (const TextureTap& tap : taps) {
    EXPECT_NEAR(tap.weight, 1.0 / 48.0, (1.0 / 1000.0 + 1.0 / 333333.0) / 48.0);
    sum += tap.weight;
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

TEST(TextureTaps, BoxOfNoWidthHasNoTaps) {
  EXPECT_TRUE(box_taps(4, 4, Vec2(0.3, 0.3), 0.0, 1.0).empty());
  EXPECT_TRUE(box_taps(4, 4, Vec2(0.3, 0.3), 1.0, NAN).empty());
  EXPECT_TRUE(box_taps(4, 4, Vec2(0.3, 0.3), INFINITY, 1.0).empty());
}

TEST(TextureTaps, BoxOfOneTexelOnItsCentreIsThatTexel) {
  const auto taps = box_taps(4, 4, Vec2(2.5 / 4, 1.0 - 1.5 / 4), 0.5, 0.5);
  ASSERT_EQ(taps.size(), 1u);
  EXPECT_EQ(taps[0].x, 2u);
  EXPECT_EQ(taps[0].row, 1u);
  EXPECT_DOUBLE_EQ(taps[0].weight, 1.0);
}

}  // namespace
}  // namespace mbk
