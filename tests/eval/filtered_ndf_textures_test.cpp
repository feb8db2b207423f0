// Trilinear lookups in `sh` and `vmf` assets (libbake/eval/filtered_ndf_textures.h): a lookup at a texel's
// centre and integer lod is that texel; level 0 of an SH pyramid interpolates Y_lm of the normals, so the
// corner shared by a 2x2 block equals the level-1 texel above it; blends between levels are linear; vMF lookups
// interpolate (alpha, alpha r) (Alg. 7.2), not kappa and mu, merged by direction; a footprint probe is read as its
// four quarters, or from 8 texels up as the texels its box covers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "libbake/eval/filtered_ndf_textures.h"
#include "libbake/filter/sh_asset.h"
#include "libbake/filter/vmf_asset.h"
#include "libbake/image/texture_taps.h"
#include "tests/filter/filter_test_maps.h"

namespace mbk {
namespace {

Vec2 centre_uv(uint32_t w, uint32_t h, uint32_t x, uint32_t row) { return Vec2((x + 0.5) / w, 1.0 - (row + 0.5) / h); }

Asset sh_asset(const NormalMap& map, int order) {
  return Asset::parse(
      bake_sh_asset(test::loaded_map(map), {order, ShPrecision::f32, ShWindow::hann}, Progress::silent()).serialize(),
      "sh");
}

TEST(ShNdfTexture, TexelCentresAndLevelBlends) {
  const NormalMap map = test::random_normal_map(8, 8, 21);
  const Asset a = sh_asset(map, 4);
  const ShNdfTexture t = ShNdfTexture::from_asset(a);
  EXPECT_EQ(t.levels(), 4u);
  EXPECT_EQ(t.window().size(), 5u);
  const ShBasisEvaluator basis(4);
  std::vector<double> g(25), g1(25), g2(25);
  // Level 0 at a texel centre: Y_lm of its normal.
  t.lookup(centre_uv(8, 8, 3, 5), 0.0, g);
  const auto y = basis.evaluate(map.at(3, 5).cast<double>());
  for (int k = 0; k < 25; ++k) EXPECT_NEAR(g[size_t(k)], y[size_t(k)], 1e-6);
  // Level 1 at a texel centre: the stored texel (the mean of its four deltas). Level 0 looked up at the block's
  // shared corner is one delta at the renormalised mean of the four normals instead (as plain normal mapping).
  const std::vector<float> level1 = a.read<float>("level_1");
  t.lookup(centre_uv(4, 4, 1, 2), 1.0, g1);
  t.lookup(centre_uv(4, 4, 1, 2), 0.0, g2);
  const Vec3 corner = (map.at(2, 4) + map.at(3, 4) + map.at(2, 5) + map.at(3, 5)).cast<double>().normalized();
  const auto y_corner = basis.evaluate(corner);
  for (int k = 0; k < 25; ++k) {
    EXPECT_NEAR(g1[size_t(k)], level1[(2 * 4 + 1) * 25 + size_t(k)], 1e-7);
    EXPECT_NEAR(g2[size_t(k)], y_corner[size_t(k)], 1e-6);
  }
  // Between levels: linear.
  const Vec2 uv(0.3, 0.71);
  t.lookup(uv, 1.0, g1);
  t.lookup(uv, 2.0, g2);
  t.lookup(uv, 1.25, g);
  for (int k = 0; k < 25; ++k) EXPECT_NEAR(g[size_t(k)], 0.75 * g1[size_t(k)] + 0.25 * g2[size_t(k)], 1e-12);
  t.lookup(Vec2(NAN, 0.5), 0.0, g);
  EXPECT_TRUE(std::isnan(g[0]));
}

TEST(ShNdfTexture, ReportsTheFinestLevelsDeltaAndItsWeight) {
  // The sh shader shades a lookup's finest-level part as one normal: the lookup names it (the renormalised bilinear
  // normal) with weight 1 - t, and g = that weight times Y(normal) plus the coarser level's share.
  const NormalMap map = test::random_normal_map(8, 8, 22);
  const ShNdfTexture t = ShNdfTexture::from_asset(sh_asset(map, 4));
  const ShBasisEvaluator basis(4);
  std::vector<double> g(25), g0(25), g1(25);
  const Vec2 corner_uv = centre_uv(4, 4, 1, 2);
  const Vec3 corner = (map.at(2, 4) + map.at(3, 4) + map.at(2, 5) + map.at(3, 5)).cast<double>().normalized();
  for (const double lod : {0.0, 0.3, 0.99}) {
    ShNdfTexture::FinestDelta delta;
    t.lookup(corner_uv, lod, g, &delta);
    EXPECT_NEAR(delta.weight, 1.0 - lod, 1e-12) << lod;
    EXPECT_LT((delta.normal - corner).norm(), 1e-6) << lod;
    t.lookup(corner_uv, 0.0, g0);
    t.lookup(corner_uv, 1.0, g1);
    for (int k = 0; k < 25; ++k) EXPECT_NEAR(g[size_t(k)], delta.weight * g0[size_t(k)] + lod * g1[size_t(k)], 1e-12);
  }
  for (const double lod : {1.0, 1.5, 3.0}) {
    ShNdfTexture::FinestDelta delta{0.5, Vec3::UnitX()};
    t.lookup(corner_uv, lod, g, &delta);
    EXPECT_EQ(delta.weight, 0.0) << lod;
  }
}

TEST(VmfTexture, InterpolatesPremultipliedLobes) {
  // Two columns of different constant normals: level 0 holds (1, n) in slot 0 for both.
  NormalMap map;
  map.width = 2, map.height = 1;
  const Vec3 a = Vec3(0.6, 0, 0.8), b = Vec3(-0.6, 0, 0.8);
  map.texels = {a.cast<float>(), b.cast<float>()};
  VmfBakeOptions options{2, {}};
  const VmfPyramid p = build_vmf_pyramid(map, nullptr, options, Progress::silent());
  const Asset asset = Asset::parse(vmf_asset_writer(test::loaded_map(map), nullptr, p, options).serialize(), "vmf");
  const VmfTexture t = VmfTexture::from_asset(asset);
  ASSERT_EQ(t.levels(), 2u);
  // At texel 0's centre: the lobe (1, a), kappa at the cap.
  auto lobes = t.lookup(centre_uv(2, 1, 0, 0), 0.0);
  double total = 0;
  for (const auto& l : lobes)
    if (l.alpha > 0) {
      total += l.alpha;
      EXPECT_LT((l.mu - a).norm(), 1e-6);
      EXPECT_EQ(l.kappa, 1e6);
    }
  EXPECT_NEAR(total, 1.0, 1e-7);
  // Halfway between the texels at lod 0: one lobe (of J + 1 slots) at the renormalised interpolated normal with
  // kappa at the cap, as plain normal mapping shades it, not the taps' two lobes or a broad blend.
  lobes = t.lookup(Vec2(0.5, 0.5), 0.0);
  ASSERT_EQ(lobes.size(), 3u);
  EXPECT_NEAR(lobes[0].alpha, 1.0, 1e-7);
  EXPECT_LT((lobes[0].mu - Vec3::UnitZ()).norm(), 1e-6);
  EXPECT_EQ(lobes[0].kappa, 1e6);
  EXPECT_EQ(lobes[1].alpha, 0.0);
  EXPECT_EQ(lobes[2].alpha, 0.0);
  // Between levels 0 and 1 (lod 0.25): 0.75 of that lobe, and 0.25 of the coarse level's two facets, each still
  // its own lobe (the merge keeps atoms of different directions apart).
  const auto top = t.lookup(Vec2(0.5, 0.5), 1.0);
  ASSERT_EQ(top.size(), 2u);
  const auto between = t.lookup(Vec2(0.5, 0.5), 0.25);
  ASSERT_EQ(between.size(), 3u);
  EXPECT_NEAR(between[0].alpha, 0.75, 1e-7);
  EXPECT_LT((between[0].mu - Vec3::UnitZ()).norm(), 1e-6);
  for (const auto& facet : top) {
    ASSERT_GT(facet.alpha, 0.0);
    const auto it = std::find_if(between.begin() + 1, between.end(),
                                 [&](const VmfLobeShape& l) { return (l.mu - facet.mu).norm() < 1e-6; });
    ASSERT_NE(it, between.end());
    EXPECT_NEAR(it->alpha, 0.25 * facet.alpha, 1e-7);
    EXPECT_NEAR(it->kappa, facet.kappa, 1e-6 * facet.kappa);
  }
}

// The mean resultant sum_j alpha_j A(kappa_j) mu_j of a lookup's lobes: the NDF's first moment (the merge and
// the fit conserve it), whose length is 1 minus the spread of the normals the footprint covers.
Vec3 mean_resultant(const std::vector<VmfLobeShape>& lobes) {
  Vec3 r = Vec3::Zero();
  for (const VmfLobeShape& l : lobes)
    if (l.alpha > 0.0) r += l.alpha * vmf_mean_length(l.kappa) * l.mu;
  return r;
}

TEST(VmfTexture, FootprintsReadTheSpreadOfTheNormalsTheyCover) {
  // A footprint a few texels wide covers a spread of interpolated normals; one trilinear read at its level takes
  // the field at one point below level 1 (a delta, no spread) and reaches beyond the box above it. Read as its
  // quarters (below 8 texels) or as the level-k texels its box covers (from 8 up), the lookup's first moment must
  // be closer to the brute-force mean of the renormalised bilinear normals over the box (a 24 x 24 lattice in it)
  // than one read's, for boxes of 1.2 to 24 texels. Measured mean |R - R_brute| (this lookup / one read / the box's
  // spread 1 - |R_brute|): 1.2 texels 0.0045 / 0.019 / 0.0057, 2: 0.011 / 0.028 / 0.014, 3: 0.021 / 0.032 / 0.028,
  // 6: 0.024 / 0.070 / 0.059, 12 (box): 0.011 / 0.051 / 0.061 (0.034 read as quarters), 24 (box): 0.011 / 0.015 /
  // 0.062 (what is left is the fitted texels' first moment against the bilinear field's over partly covered texels).
  constexpr uint32_t kSize = 64;
  NormalMap map;
  map.width = map.height = kSize;
  for (uint32_t row = 0; row < kSize; ++row)
    for (uint32_t x = 0; x < kSize; ++x) {
      const double u = 2 * M_PI * x / 7.0, v = 2 * M_PI * row / 9.0;
      map.texels.push_back(
          Vec3(0.45 * std::sin(u + 0.3 * v), 0.35 * std::cos(v - 0.5 * u), 1.0).normalized().cast<float>());
    }
  VmfBakeOptions options{4, {}};
  const VmfPyramid p = build_vmf_pyramid(map, nullptr, options, Progress::silent());
  const VmfTexture t = VmfTexture::from_asset(
      Asset::parse(vmf_asset_writer(test::loaded_map(map), nullptr, p, options).serialize(), "vmf"));
  const auto bilinear_normal = [&](const Vec2& uv) {
    Vec3 n = Vec3::Zero();
    for (const TextureTap& tap : bilinear_taps(kSize, kSize, uv))
      n += tap.weight * map.at(tap.x, tap.row).cast<double>();
    return n.normalized();
  };
  for (const double width : {1.2, 2.0, 3.0, 6.0, 12.0, 24.0}) {
    double error_lookup = 0.0, error_one_read = 0.0, spread = 0.0;
    constexpr int kFootprints = 60;
    for (int i = 0; i < kFootprints; ++i) {
      const Vec2 uv(0.137 + 0.61803 * i - std::floor(0.137 + 0.61803 * i),
                    0.71 + 0.41421 * i - std::floor(0.71 + 0.41421 * i));
      Vec3 brute = Vec3::Zero();
      constexpr int kLattice = 24;
      for (int b = 0; b < kLattice; ++b)
        for (int a = 0; a < kLattice; ++a)
          brute += bilinear_normal(uv + width / kSize * Vec2((a + 0.5) / kLattice - 0.5, (b + 0.5) / kLattice - 0.5));
      brute /= double(kLattice * kLattice);
      FootprintProbes probe;
      const double lod = std::max(0.0, std::log2(width) - kLodOfBoxVariance);
      probe.push_back({uv, lod, width});
      error_lookup += (mean_resultant(t.lookup(probe)) - brute).norm() / kFootprints;
      error_one_read += (mean_resultant(t.lookup(uv, lod)) - brute).norm() / kFootprints;
      spread += (1.0 - brute.norm()) / kFootprints;
    }
    std::cout << "box " << width << " texels: mean |R - R_brute| lookup " << error_lookup << ", one read "
              << error_one_read << " (the box's spread 1 - |R_brute| " << spread << ")\n";
    if (width < 2.0 * kVmfBoxTexelsPerWidth) {
      EXPECT_LT(error_lookup, 0.75 * error_one_read) << width;
    } else {
      EXPECT_LT(error_lookup, error_one_read) << width;
      EXPECT_LT(error_lookup, 0.3 * spread) << width;  // the box's spread, mostly captured
    }
    if (width <= 2.0) {
      EXPECT_LT(error_lookup, spread) << width;  // the spread one read ignores, mostly captured
    }
  }
}

TEST(VmfTexture, AFootprintAcrossAnEdgeKeepsBothNormalsAsAtoms) {
  // Two flat halves meeting at a sharp edge (columns 0-7 normal a, 8-15 normal b). A footprint of 3 texels centred
  // on the edge is read at four points, two on each side, where the interpolated normal is exactly a or b: each
  // read's delta joins the merge by direction, so the lookup holds two atoms (kappa_max) of weight 1/2, not one
  // lobe at normalize(a + b) whose spread stands for the two (what summing the reads' deltas into one lobe gave).
  constexpr uint32_t kSize = 16;
  const Vec3 a = Vec3(0.5, 0.0, 1.0).normalized(), b = Vec3(-0.4, 0.2, 1.0).normalized();
  NormalMap map;
  map.width = map.height = kSize;
  for (uint32_t row = 0; row < kSize; ++row)
    for (uint32_t x = 0; x < kSize; ++x) map.texels.push_back((x < kSize / 2 ? a : b).cast<float>());
  VmfBakeOptions options{2, {}};
  const VmfPyramid p = build_vmf_pyramid(map, nullptr, options, Progress::silent());
  const VmfTexture t = VmfTexture::from_asset(
      Asset::parse(vmf_asset_writer(test::loaded_map(map), nullptr, p, options).serialize(), "vmf"));
  FootprintProbes probe;
  const double width = 3.0;
  probe.push_back({Vec2(0.5, 0.37), std::max(0.0, std::log2(width) - kLodOfBoxVariance), width});
  int atoms = 0;
  for (const VmfLobeShape& l : t.lookup(probe)) {
    if (!(l.alpha > 0.0)) continue;
    ++atoms;
    EXPECT_NEAR(l.alpha, 0.5, 1e-7);
    EXPECT_EQ(l.kappa, 1e6);
    EXPECT_LT(std::min((l.mu - a).norm(), (l.mu - b).norm()), 1e-6);
  }
  EXPECT_EQ(atoms, 2);
}

VmfTexture vmf_texture(const NormalMap& map, int lobes) {
  VmfBakeOptions options{lobes, {}};
  const VmfPyramid p = build_vmf_pyramid(map, nullptr, options, Progress::silent());
  return VmfTexture::from_asset(
      Asset::parse(vmf_asset_writer(test::loaded_map(map), nullptr, p, options).serialize(), "vmf"));
}

TEST(VmfTexture, WideFootprintsReadOnlyTheTexelsTheirBoxCovers) {
  // Flat ground (normal a) with a band of another normal b in columns 44-51 of a 64 x 64 map. A footprint 16
  // texels wide centred on column 34 covers columns 26-42, the band 2 texels beyond its edge. Read as a box of
  // level-2 texels (4 wide: columns 24-44), the lookup is the flat ground's normal alone: its first moment
  // sum alpha A(kappa) mu is a. Read as its quarters (what a probe this wide was before: four trilinear reads of
  // width 8 at +-4 texels, lod - 1), level 3's texel over columns 40-48 draws b in.
  constexpr uint32_t kSize = 64;
  const Vec3 a = Vec3(0.1, -0.05, 1.0).normalized(), b = Vec3(-0.6, 0.3, 1.0).normalized();
  NormalMap map;
  map.width = map.height = kSize;
  for (uint32_t row = 0; row < kSize; ++row)
    for (uint32_t x = 0; x < kSize; ++x) map.texels.push_back((x >= 44 && x < 52 ? b : a).cast<float>());
  const VmfTexture t = vmf_texture(map, 2);
  const double width = 16.0, lod = std::log2(width) - kLodOfBoxVariance;
  for (const double row : {7.5, 30.0, 51.25}) {
    const Vec2 uv(34.0 / kSize, 1.0 - row / kSize);
    FootprintProbes probe, quarters;
    probe.push_back({uv, lod, width});
    for (const double dy : {-1.0, 1.0})
      for (const double dx : {-1.0, 1.0})  // no finite width: each read as it is
        quarters.push_back({uv + 0.25 * width / kSize * Vec2(dx, dy), lod - 1.0, INFINITY});
    const double box_error = (mean_resultant(t.lookup(probe)) - a).norm();
    const double quarters_error = (mean_resultant(t.lookup(quarters)) - a).norm();
    std::cout << "row " << row << ": |R - a| box " << box_error << ", quarters " << quarters_error << "\n";
    EXPECT_LT(box_error, 1e-5) << row;
    EXPECT_GT(quarters_error, 1e-3) << row;  // the leak the box removes
  }
}

TEST(VmfTexture, BoxReadsOnOddAndStripMapsMatchTheBruteForceMean) {
  // Maps whose sides are not powers of two or differ a lot (a level-k texel is then not 2^k finest texels, and
  // the short side reaches one texel long before the long one): the box read's first moment against the mean
  // of the finest normals over the box (a 32 x 32 lattice of texel lookups, wrapping), for widths from 8 to far
  // beyond the map (10^6 texels: the whole map, read as the top level's one texel, at most a handful of taps).
  for (const auto& [w, h] : {std::pair{48u, 20u}, std::pair{200u, 6u}, std::pair{33u, 33u}}) {
    NormalMap map;
    map.width = w, map.height = h;
    for (uint32_t row = 0; row < h; ++row)
      for (uint32_t x = 0; x < w; ++x)
        map.texels.push_back(Vec3(0.4 * std::sin(0.9 * x + 0.2 * row), 0.3 * std::cos(0.7 * row - 0.4 * x), 1.0)
                                 .normalized()
                                 .cast<float>());
    const VmfTexture t = vmf_texture(map, 3);
    Vec3 whole = Vec3::Zero();
    for (const Vec3f& n : map.texels) whole += n.cast<double>() / double(map.texels.size());
    for (const double width : {8.0, 13.0, 40.0, 1e6}) {
      const Vec2 uv(0.31, 0.57);
      const Vec2 c = texel_coordinates(uv, w, h);
      Vec3 brute = Vec3::Zero();
      constexpr int kLattice = 32;
      for (int b = 0; b < kLattice; ++b)
        for (int a = 0; a < kLattice; ++a) {
          const double x = c.x() + width * ((a + 0.5) / kLattice - 0.5),
                       y = c.y() + width * ((b + 0.5) / kLattice - 0.5);
          const auto wrap = [](double v, uint32_t n) { return uint32_t(v - n * std::floor(v / n)) % n; };
          brute += map.at(wrap(x, w), wrap(y, h)).cast<double>() / double(kLattice * kLattice);
        }
      if (width == 1e6) brute = whole;  // the lattice cannot sample a box this wide evenly
      FootprintProbes probe;
      probe.push_back({uv, std::log2(width) - kLodOfBoxVariance, width});
      const double error = (mean_resultant(t.lookup(probe)) - brute).norm();
      std::cout << w << "x" << h << " box " << width << ": |R - R_brute| " << error << "\n";
      EXPECT_LT(error, 0.02) << w << "x" << h << " width " << width;
    }
  }
}

TEST(FilteredNdfTextures, RefuseTheWrongKind) {
  const NormalMap map = test::random_normal_map(4, 4, 2);
  const Asset a = sh_asset(map, 2);
  EXPECT_THROW(VmfTexture::from_asset(a), Error);
}

}  // namespace
}  // namespace mbk
