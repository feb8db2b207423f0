// NormalPyramid against brute force: level sizes follow the GPU's floor rule; every texel of every level is the
// area-weighted mean of the finest texels over its rectangle (formats/mip_levels.h), for odd and degenerate
// sizes; a lookup at a texel's centre returns the box average of level 0 over the uv footprint of that texel
// (positions line up with coverage); bilinear lookups wrap at the borders; trilinear lookups blend the two
// levels around the lod.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

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

// Length of the overlap of [a, b) and [c, d).
double overlap(double a, double b, double c, double d) { return std::max(0.0, std::min(b, d) - std::max(a, c)); }

// Area-weighted mean of the map over [x0, x1) x [r0, r1) in continuous texel coordinates (x right, row down),
// by brute force over every texel.
Vec3 box_average(const NormalMap& m, double x0, double x1, double r0, double r1) {
  Vec3 sum = Vec3::Zero();
  double area = 0;
  for (uint32_t y = 0; y < m.height; ++y)
    for (uint32_t x = 0; x < m.width; ++x) {
      const double a = overlap(x0, x1, x, x + 1.0) * overlap(r0, r1, y, y + 1.0);
      sum += a * m.at(x, y).cast<double>();
      area += a;
    }
  return sum / area;
}

// Texel (i, j) of a w x h level covers [i W / w, (i+1) W / w) x [j H / h, (j+1) H / h) of the finest texels.
Vec3 brute_force_mean(const NormalMap& m, uint32_t w, uint32_t h, uint32_t i, uint32_t j) {
  const double tx = double(m.width) / w, ty = double(m.height) / h;
  return box_average(m, i * tx, (i + 1) * tx, j * ty, (j + 1) * ty);
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
        EXPECT_NEAR(
            (p.levels[k].at(i, j).cast<double>() - brute_force_mean(map, sizes[k].width, sizes[k].height, i, j)).norm(),
            0.0, 2e-7)
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

// At integer lod k, a lookup at the centre of a level-k texel returns the box average of level 0 over the uv
// rectangle that texel occupies when the level divides [0, 1] evenly: 1 / w_k wide around the centre. This
// holds only if what a texel covers is where sampling puts it (the old ceil rule failed it: for W = 5, its
// last texel of level 2 held column 4 alone but was sampled at u = 0.75).
TEST_P(PyramidSizes, LookupsAtTexelCentresSeeWhatTheTexelCovers) {
  const auto [w, h] = GetParam();
  const NormalMap map = hashed_map(w, h);
  const NormalPyramid p = build_normal_pyramid(map);
  for (uint32_t k = 0; k < p.levels.size(); ++k) {
    const uint32_t lw = std::max(1u, w >> k), lh = std::max(1u, h >> k);
    for (uint32_t r = 0; r < lh; ++r)
      for (uint32_t x = 0; x < lw; ++x) {
        const Vec2 uv((x + 0.5) / lw, 1.0 - (r + 0.5) / lh);
        const double u0 = uv.x() - 0.5 / lw, u1 = uv.x() + 0.5 / lw;
        const double t0 = (1.0 - uv.y()) - 0.5 / lh, t1 = (1.0 - uv.y()) + 0.5 / lh;  // rows, as a fraction of h
        const Vec3 expected = box_average(map, u0 * w, u1 * w, t0 * h, t1 * h);
        EXPECT_NEAR((sample_pyramid(p, uv, double(k)) - expected).norm(), 0.0, 3e-7)
            << w << "x" << h << " level " << k << " texel (" << x << ", " << r << ")";
      }
  }
}

INSTANTIATE_TEST_SUITE_P(OddAndDegenerate, PyramidSizes,
                         ::testing::Values(std::pair{1u, 1u}, std::pair{5u, 3u}, std::pair{1u, 7u}, std::pair{7u, 1u},
                                           std::pair{8u, 8u}, std::pair{13u, 6u}, std::pair{33u, 17u},
                                           std::pair{257u, 9u}));

// Level k is max(1, floor(W / 2^k)) x max(1, floor(H / 2^k)), down to 1 x 1.
TEST(MipLevels, SizesFollowTheGpuFloorRule) {
  auto widths_heights = [](uint32_t w, uint32_t h) {
    std::vector<std::pair<uint32_t, uint32_t>> out;
    for (const LevelSize& s : mip_level_sizes(w, h)) out.emplace_back(s.width, s.height);
    return out;
  };
  using P = std::vector<std::pair<uint32_t, uint32_t>>;
  EXPECT_EQ(widths_heights(5, 3), (P{{5, 3}, {2, 1}, {1, 1}}));
  EXPECT_EQ(widths_heights(33, 17), (P{{33, 17}, {16, 8}, {8, 4}, {4, 2}, {2, 1}, {1, 1}}));
  EXPECT_EQ(widths_heights(257, 9), (P{{257, 9}, {128, 4}, {64, 2}, {32, 1}, {16, 1}, {8, 1}, {4, 1}, {2, 1}, {1, 1}}));
  EXPECT_EQ(widths_heights(1, 7), (P{{1, 7}, {1, 3}, {1, 1}}));
  EXPECT_EQ(widths_heights(8, 8), (P{{8, 8}, {4, 4}, {2, 2}, {1, 1}}));
  EXPECT_EQ(widths_heights(1, 1), (P{{1, 1}}));
  EXPECT_TRUE(mip_level_sizes(0, 5).empty());
  EXPECT_TRUE(mip_level_sizes(5, 0).empty());
  // L = 1 + floor(log2(max(W, H))), also at the top of the range.
  EXPECT_EQ(mip_level_sizes(4096, 3).size(), 13u);
  EXPECT_EQ(mip_level_sizes(4095, 3).size(), 12u);
  EXPECT_EQ(mip_level_sizes(0xFFFFFFFFu, 1).size(), 32u);
}

// Each texel's weights sum to 1, and each finest texel is shared out completely: its weights over all level
// texels sum to level_extent / extent (a level texel is extent / level_extent finest texels long).
TEST(MipLevels, TexelWeightsPartitionTheAxis) {
  for (auto [n, e] : {std::pair{1u, 1u}, {1u, 5u}, {2u, 5u}, {3u, 7u}, {128u, 257u}, {4u, 16u}, {9u, 9u}}) {
    const auto texels = mip_texel_weights(n, e);
    ASSERT_EQ(texels.size(), n);
    std::vector<double> share(e, 0.0);
    for (const auto& list : texels) {
      double sum = 0;
      for (size_t q = 0; q < list.size(); ++q) {
        ASSERT_LT(list[q].index, e);
        if (q > 0) {
          EXPECT_EQ(list[q].index, list[q - 1].index + 1);
        }
        EXPECT_GT(list[q].weight, 0.0);
        sum += list[q].weight;
        share[list[q].index] += list[q].weight;
      }
      EXPECT_NEAR(sum, 1.0, 1e-15) << n << " of " << e;
    }
    for (uint32_t x = 0; x < e; ++x) EXPECT_NEAR(share[x], double(n) / e, 1e-15) << n << " of " << e << " at " << x;
  }
  // Power of two: plain 4-texel blocks with weight exactly 1/4.
  const auto blocks = mip_texel_weights(4, 16);
  for (uint32_t i = 0; i < 4; ++i) {
    ASSERT_EQ(blocks[i].size(), 4u);
    for (uint32_t q = 0; q < 4; ++q) {
      EXPECT_EQ(blocks[i][q].index, 4 * i + q);
      EXPECT_EQ(blocks[i][q].weight, 0.25);
    }
  }
  // 2 texels over 5: [0, 2.5) and [2.5, 5), the middle column split in halves.
  const auto halves = mip_texel_weights(2, 5);
  ASSERT_EQ(halves[0].size(), 3u);
  EXPECT_EQ(halves[0][2].index, 2u);
  EXPECT_EQ(halves[0][2].weight, 0.5 / 2.5);
  EXPECT_EQ(halves[1][0].index, 2u);
  EXPECT_EQ(halves[1][0].weight, 0.5 / 2.5);
  EXPECT_THROW(mip_texel_weights(0, 5), Error);
  EXPECT_THROW(mip_texel_weights(6, 5), Error);
}

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
  const Vec3 mean = brute_force_mean(p.levels[0], 1, 1, 0, 0);
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
