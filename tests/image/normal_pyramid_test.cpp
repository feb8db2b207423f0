// NormalPyramid against brute force: every texel of every level is the mean of the finest texels it covers
// (formats/mip_levels.h), for odd and degenerate sizes; bilinear lookups return texel values at texel
// centres and wrap at the borders; trilinear lookups blend the two levels around the lod.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/error.h"
#include "formats/mip_levels.h"
#include "libbake/core/hash.h"
#include "libbake/image/normal_pyramid.h"

namespace mbk {
namespace {

// Unit normals from an integer hash: varied directions, upper hemisphere.
NormalMap hashed_map(uint32_t w, uint32_t h, uint32_t seed = 7) {
  NormalMap m;
  m.width = w;
  m.height = h;
  for (uint32_t i = 0; i < w * h; ++i) {
    const uint32_t k = hash_combine(seed, i);
    const Vec3 n(unit_from_hash(k) - 0.5, unit_from_hash(pcg_hash(k)) - 0.5, 0.3 + unit_from_hash(pcg_hash(k + 1)));
    m.texels.push_back(n.normalized().cast<float>());
  }
  return m;
}

Vec3 brute_force_mean(const NormalMap& m, uint32_t level, uint32_t i, uint32_t j) {
  Vec3 sum = Vec3::Zero();
  int count = 0;
  for (uint32_t y = j << level; y < std::min(m.height, (j + 1) << level); ++y)
    for (uint32_t x = i << level; x < std::min(m.width, (i + 1) << level); ++x, ++count)
      sum += m.at(x, y).cast<double>();
  return sum / count;
}

Vec2 centre_uv(const NormalMap& level, uint32_t x, uint32_t row) {
  return {(x + 0.5) / level.width, 1.0 - (row + 0.5) / level.height};
}

class PyramidSizes : public ::testing::TestWithParam<std::pair<uint32_t, uint32_t>> {};

TEST_P(PyramidSizes, EachLevelIsTheBruteForceMeanOfCoveredTexels) {
  const auto [w, h] = GetParam();
  const NormalMap map = hashed_map(w, h);
  const NormalPyramid p = build_normal_pyramid(map);
  const auto sizes = mip_level_sizes(w, h);
  ASSERT_EQ(p.levels.size(), sizes.size());
  EXPECT_EQ(p.levels[0].texels, map.texels);
  for (uint32_t k = 0; k < sizes.size(); ++k) {
    ASSERT_EQ(p.levels[k].width, sizes[k].width);
    ASSERT_EQ(p.levels[k].height, sizes[k].height);
    for (uint32_t j = 0; j < sizes[k].height; ++j)
      for (uint32_t i = 0; i < sizes[k].width; ++i)
        EXPECT_NEAR((p.levels[k].at(i, j).cast<double>() - brute_force_mean(map, k, i, j)).norm(), 0.0, 2e-7)
            << "level " << k << " texel (" << i << ", " << j << ")";
  }
  EXPECT_EQ(p.levels.back().texels.size(), 1u);
}

TEST_P(PyramidSizes, BilinearAtTexelCentresReturnsTexels) {
  const auto [w, h] = GetParam();
  const NormalPyramid p = build_normal_pyramid(hashed_map(w, h));
  for (const NormalMap& level : p.levels)
    for (uint32_t r = 0; r < level.height; ++r)
      for (uint32_t x = 0; x < level.width; ++x) {
        const Vec3 expected = level.at(x, r).cast<double>();
        EXPECT_NEAR((sample_bilinear(level, centre_uv(level, x, r)) - expected).norm(), 0.0, 1e-12);
        // Tiling: whole periods of uv change nothing.
        EXPECT_NEAR((sample_bilinear(level, centre_uv(level, x, r) + Vec2(3.0, -2.0)) - expected).norm(), 0.0, 1e-9);
      }
}

INSTANTIATE_TEST_SUITE_P(OddAndDegenerate, PyramidSizes,
                         ::testing::Values(std::pair{1u, 1u}, std::pair{5u, 3u}, std::pair{1u, 7u}, std::pair{7u, 1u},
                                           std::pair{8u, 8u}, std::pair{13u, 6u}, std::pair{33u, 17u}));

TEST(NormalPyramid, BilinearWrapsAcrossTheBorders) {
  const NormalMap m = hashed_map(5, 3);
  // u = 0 lies halfway between the centres of the last and the first column.
  const Vec2 left_edge(0.0, 1.0 - 1.5 / 3.0);
  const Vec3 expected = 0.5 * (m.at(4, 1).cast<double>() + m.at(0, 1).cast<double>());
  EXPECT_NEAR((sample_bilinear(m, left_edge) - expected).norm(), 0.0, 1e-12);
  // v = 1 (top edge) lies halfway between the bottom and the top row.
  const Vec2 top_edge((2 + 0.5) / 5.0, 1.0);
  const Vec3 expected_v = 0.5 * (m.at(2, 2).cast<double>() + m.at(2, 0).cast<double>());
  EXPECT_NEAR((sample_bilinear(m, top_edge) - expected_v).norm(), 0.0, 1e-12);
  // A corner mixes the four corner texels equally.
  const Vec3 corners = 0.25 * (m.at(0, 0).cast<double>() + m.at(4, 0).cast<double>() + m.at(0, 2).cast<double>() +
                               m.at(4, 2).cast<double>());
  EXPECT_NEAR((sample_bilinear(m, Vec2(0.0, 0.0)) - corners).norm(), 0.0, 1e-12);
}

TEST(NormalPyramid, BilinearInterpolatesLinearlyBetweenCentres) {
  const NormalMap m = hashed_map(4, 4);
  const Vec2 a = centre_uv(m, 1, 2), b = centre_uv(m, 2, 2);
  for (double t : {0.1, 0.25, 0.5, 0.9}) {
    const Vec3 expected = (1 - t) * m.at(1, 2).cast<double>() + t * m.at(2, 2).cast<double>();
    EXPECT_NEAR((sample_bilinear(m, (1 - t) * a + t * b) - expected).norm(), 0.0, 1e-12);
  }
}

TEST(NormalPyramid, TrilinearBlendsTheTwoLevelsAroundLod) {
  const NormalPyramid p = build_normal_pyramid(hashed_map(13, 6));
  const Vec2 uv(0.37, 0.81);
  EXPECT_NEAR((sample_pyramid(p, uv, 0.0) - sample_bilinear(p.levels[0], uv)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((sample_pyramid(p, uv, 2.0) - sample_bilinear(p.levels[2], uv)).norm(), 0.0, 1e-15);
  const Vec3 blend = 0.75 * sample_bilinear(p.levels[1], uv) + 0.25 * sample_bilinear(p.levels[2], uv);
  EXPECT_NEAR((sample_pyramid(p, uv, 1.25) - blend).norm(), 0.0, 1e-12);
  // Clamped to the pyramid: below 0 is level 0, beyond the top is the 1 x 1 level (the map's mean).
  EXPECT_NEAR((sample_pyramid(p, uv, -3.0) - sample_bilinear(p.levels[0], uv)).norm(), 0.0, 1e-15);
  const Vec3 mean = brute_force_mean(p.levels[0], uint32_t(p.levels.size() - 1), 0, 0);
  EXPECT_NEAR((sample_pyramid(p, uv, 1e9) - mean).norm(), 0.0, 1e-7);
  EXPECT_NEAR((sample_pyramid(p, uv, INFINITY) - mean).norm(), 0.0, 1e-7);
  EXPECT_TRUE(std::isnan(sample_pyramid(p, uv, NAN).x()));
  EXPECT_TRUE(std::isnan(sample_pyramid(p, Vec2(NAN, 0.5), 0.0).x()));
}

TEST(NormalPyramid, MeanLengthShrinksWhereNormalsDisagree) {
  // A constant map keeps unit length at every level; a two-valued V-groove map does not.
  NormalMap flat;
  flat.width = 6, flat.height = 5;
  flat.texels.assign(30, Vec3f(0.6f, 0.0f, 0.8f));
  for (const NormalMap& level : build_normal_pyramid(flat).levels)
    for (const Vec3f& n : level.texels) EXPECT_NEAR(n.norm(), 1.0f, 1e-6f);
  NormalMap groove = flat;
  for (uint32_t r = 0; r < 5; ++r)
    for (uint32_t x = 0; x < 6; x += 2) groove.at(x, r) = Vec3f(-0.6f, 0.0f, 0.8f);
  const NormalPyramid p = build_normal_pyramid(groove);
  EXPECT_NEAR(p.levels[1].at(0, 0).norm(), 0.8f, 1e-6f);  // mean of +-0.6 in x: (0, 0, 0.8)
}

TEST(NormalPyramid, EmptyMapGivesEmptyPyramid) {
  EXPECT_TRUE(build_normal_pyramid(NormalMap{}).levels.empty());
  EXPECT_THROW(sample_pyramid(NormalPyramid{}, Vec2(0.5, 0.5), 0.0), Error);
}

}  // namespace
}  // namespace mbk
