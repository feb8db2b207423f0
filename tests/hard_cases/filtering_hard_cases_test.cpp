// Hard cases of the filtering bakers ([Han07]: `sh` and `vmf` assets), end to end through the asset writer, the
// reader and `validate`: a constant map, 1 x 1 and one-row maps, a two-valued V-groove, normals at 89.9 degrees,
// texels with z < 0 repaired by the loader, order 100 at the pole. Every level of every asset is compared with an
// independent computation over the finest normals the texel covers: the SH coefficients with std::sph_legendre
// (tests/hard_cases/hard_case_checks.h), the vMF lobes with the mixture's first moment, which EM keeps exactly:
// after an M-step sum_j alpha_j r_j = sum_j sum_i w_i z_ij n_i = sum_i w_i n_i (responsibilities sum to 1).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "formats/asset.h"
#include "formats/mip_levels.h"
#include "libbake/core/sh_basis.h"
#include "libbake/image/image_io.h"
#include "tests/filter/filter_test_maps.h"
#include "tests/glint/atom_maps.h"
#include "tests/hard_cases/filter_assets.h"
#include "tests/hard_cases/hard_case_checks.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

using test::bake_sh;
using test::bake_vmf;

// Every stored SH coefficient of every level against sum_i w_i Y_lm(n_i) computed independently. Tolerance: the
// storage's rounding (f16: half an ulp of an 11-bit significand; f32: 1e-6 relative) plus 2e-6 of accumulation.
void expect_sh_levels_are_means_of_the_basis(const Asset& a, const NormalMap& map, int order, ShPrecision precision) {
  const auto sizes = mip_level_sizes(map.width, map.height);
  const double relative = precision == ShPrecision::f16 ? 1.0 / 2048 : 1e-6;
  for (size_t k = 1; k < sizes.size(); ++k) {
    const std::vector<float> g = a.read_as_float("level_" + std::to_string(k));
    const uint32_t w = sizes[k].width, h = sizes[k].height;
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x)
        for (int l = 0; l <= order; ++l)
          for (int m = -l; m <= l; ++m) {
            double exact = 0.0;
            test::for_each_covered_normal(
                map, w, h, x, y, [&](const Vec3& n, double wt) { exact += wt * test::independent_sh(l, m, n); });
            const float stored = g[(size_t(y) * w + x) * size_t(sh_count(order)) + size_t(sh_index(l, m))];
            ASSERT_NEAR(stored, exact, relative * std::abs(exact) + 2e-6)
                << "level " << k << " texel (" << x << ", " << y << ") l " << l << " m " << m;
          }
  }
}

// Every vMF level's lobes: amplitudes sum to 1 and sum_j alpha_j r_j is the texel's mean normal (align 0 keeps
// r as fitted; with align > 0 only the amplitudes are checked). Returns nothing; fails with the texel.
void expect_vmf_levels_keep_mass_and_mean(const Asset& a, const NormalMap& map, int lobes, bool check_mean) {
  const auto sizes = mip_level_sizes(map.width, map.height);
  for (size_t k = 0; k < sizes.size(); ++k) {
    const std::vector<float> v = a.read_as_float("level_" + std::to_string(k));
    const uint32_t w = sizes[k].width, h = sizes[k].height;
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        Vec3 mean = Vec3::Zero(), first_moment = Vec3::Zero();
        double mass = 0.0;
        test::for_each_covered_normal(map, w, h, x, y, [&](const Vec3& n, double wt) { mean += wt * n; });
        for (int j = 0; j < lobes; ++j) {
          const float* s = &v[((size_t(y) * w + x) * size_t(lobes) + size_t(j)) * 4];
          mass += s[0];
          first_moment += Vec3(s[1], s[2], s[3]);
        }
        ASSERT_NEAR(mass, 1.0, 1e-6) << "level " << k << " texel (" << x << ", " << y << ")";
        if (check_mean) {
          ASSERT_LT((first_moment - mean).norm(), 2e-6) << "level " << k << " texel (" << x << ", " << y << ")";
        }
      }
  }
}

void expect_both_bakes_exact(const NormalMap& map, int order, int lobes) {
  for (ShPrecision p : {ShPrecision::f16, ShPrecision::f32})
    expect_sh_levels_are_means_of_the_basis(bake_sh(map, order, p), map, order, p);
  for (double align : {0.0, 1.0})
    expect_vmf_levels_keep_mass_and_mean(bake_vmf(map, lobes, align), map, lobes, align == 0);
}

// Protects against: 0 / 0 in the filtered normal of a map with no variation (a spread of exactly 0) and against
// level sizes that do not nest (13 -> 6 -> 3 -> 1, 7 -> 3 -> 1): every level must hold the constant's NDF, one
// lobe at n at the kappa cap and Y_lm(n).
TEST(HardCases, FilteringConstantMap) {
  const Vec3 n = Vec3(0.3, -0.2, 0.9).normalized();
  const NormalMap map = test::filled(13, 7, [&](uint32_t, uint32_t) { return n; });
  expect_both_bakes_exact(map, 8, 4);
  const Asset vmf = bake_vmf(map, 4, 0.0);
  const auto sizes = mip_level_sizes(13, 7);
  for (size_t k = 0; k < sizes.size(); ++k) {
    const std::vector<float> v = vmf.read_as_float("level_" + std::to_string(k));
    for (size_t t = 0; t < size_t(sizes[k].width) * sizes[k].height; ++t) {
      const VmfComponent lobe = decode_lobe(&v[t * 16], kVmfKappaMax);
      EXPECT_EQ(lobe.kappa, kVmfKappaMax) << k;
      EXPECT_LT((lobe.mu - n).norm(), 1e-6) << k;
      for (int j = 1; j < 4; ++j) EXPECT_EQ(v[t * 16 + size_t(j) * 4], 0.0f) << "level " << k << " lobe " << j;
    }
  }
}

// Protects against: a pyramid of one level (no level_1 section: 1 x 1 has nothing to filter) and one-row maps
// whose levels are 17 -> 8 -> 4 -> 2 -> 1 wide and 1 high throughout (a 2 x 1 box, never 2 x 2).
TEST(HardCases, FilteringOneByOneAndOneRowMaps) {
  const NormalMap one = test::filled(1, 1, [](uint32_t, uint32_t) { return Vec3(0.1, 0.2, 0.9); });
  const Asset sh = bake_sh(one, 6, ShPrecision::f32);
  EXPECT_EQ(sh.find("level_1"), nullptr);
  const std::vector<float> stored = sh.read<float>("normals");
  EXPECT_EQ(Vec3f(stored[0], stored[1], stored[2]), one.texels[0]);
  const Asset vmf = bake_vmf(one, 3, 0.0);
  EXPECT_EQ(vmf.find("level_1"), nullptr);
  expect_vmf_levels_keep_mass_and_mean(vmf, one, 3, true);
  expect_both_bakes_exact(test::random_normal_map(17, 1, 3), 5, 2);
}

// Protects against: a two-valued NDF (a V-groove, the case [Han07] Fig. 7.1 shows toksvig cannot hold) losing one
// facet, and more lobes than distinct normals: J = 6 lobes on two values must end as two lobes at the facets with
// the facets' area fractions (odd sizes give fractions other than 1/2), the four others empty.
TEST(HardCases, FilteringTwoValuedVGroove) {
  const Vec3 left(-0.5, 0.0, 0.866), right(0.5, 0.0, 0.866);
  const NormalMap map = test::filled(10, 6, [&](uint32_t x, uint32_t) { return x % 2 ? right : left; });
  expect_both_bakes_exact(map, 6, 6);
  const Asset vmf = bake_vmf(map, 6, 0.0);
  const auto sizes = mip_level_sizes(10, 6);
  for (size_t k = 1; k < sizes.size(); ++k) {
    const std::vector<float> v = vmf.read_as_float("level_" + std::to_string(k));
    const uint32_t w = sizes[k].width, h = sizes[k].height;
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        double right_fraction = 0.0;
        test::for_each_covered_normal(map, w, h, x, y,
                                      [&](const Vec3& n, double wt) { right_fraction += n.x() > 0 ? wt : 0.0; });
        int live = 0;
        for (int j = 0; j < 6; ++j) {
          const VmfComponent lobe = decode_lobe(&v[((size_t(y) * w + x) * 6 + size_t(j)) * 4], kVmfKappaMax);
          if (lobe.alpha == 0.0) continue;
          ++live;
          const bool is_right = lobe.mu.x() > 0;
          EXPECT_LT((lobe.mu - (is_right ? right : left).normalized()).norm(), 1e-5) << k;
          EXPECT_NEAR(lobe.alpha, is_right ? right_fraction : 1.0 - right_fraction, 1e-6) << k;
          EXPECT_GT(lobe.kappa, 1e5) << k;
        }
        EXPECT_EQ(live, right_fraction == 0.0 || right_fraction == 1.0 ? 1 : 2) << "level " << k;
      }
  }
}

// Protects against: an atom in the NDF, 50% to 99% of the texels one normal (the flat ground of scratches and panels;
// the glint LUT's hard case, tests/glint/atom_maps.h): texels mixing identical normals with a few others, where
// EM's lobes sit at the kappa cap next to broad ones. Every level's SH and vMF first moment must hold exactly.
TEST(HardCases, FilteringMapMostlyOneValue) {
  for (const test::AtomMap& m : test::atom_maps(32)) {
    if (m.name.find('%') == std::string::npos) continue;  // the constant and two-valued maps have their own cases
    SCOPED_TRACE(m.name);
    expect_both_bakes_exact(m.map, 6, 4);
  }
}

// Protects against: normals 0.1 degrees above the horizon (z = 1.7e-3), where the 1 / z of slope-based code
// blows up and a float z loses most of its digits: SH to order 16 in f32 and the vMF first moment must hold there.
TEST(HardCases, FilteringNormalsAt89Point9Degrees) {
  const double polar = (90.0 - 0.1) * std::numbers::pi / 180.0;
  const NormalMap map = test::filled(8, 8, [&](uint32_t x, uint32_t y) {
    const double azimuth = 0.7 * x + 2.3 * y;
    return Vec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
  });
  for (const Vec3f& n : map.texels) ASSERT_NEAR(n.z(), std::cos(polar), 1e-7);
  expect_sh_levels_are_means_of_the_basis(bake_sh(map, 16, ShPrecision::f32), map, 16, ShPrecision::f32);
  expect_vmf_levels_keep_mass_and_mean(bake_vmf(map, 4, 0.0), map, 4, true);
}

// Protects against: texels below the tangent plane (z < 0) reaching a baker. The loader's repair puts them on the
// horizon, (x, y, 0) / |(x, y)|, exactly; the bakes of the repaired map then hold its NDF like any other map.
TEST(HardCases, FilteringTexelsWithZBelowZeroRepaired) {
  test::ScratchDir dir;
  Image im{6, 4, 3, {}};
  for (uint32_t i = 0; i < 24; ++i) {
    const float z = i % 3 == 0 ? -0.4f - 0.1f * float(i % 4) : 0.8f;
    im.pixels.insert(im.pixels.end(), {0.3f * std::cos(float(i)), 0.3f * std::sin(float(i)), z});
  }
  save_image(dir / "below.exr", im);
  const LoadedNormalMap loaded =
      load_normal_map(dir / "below.exr", NormalMapLoadOptions{YConvention::plus_y, InvalidTexelPolicy::repair});
  EXPECT_EQ(loaded.record.repaired_texels, 8u);
  for (uint32_t i = 0; i < 24; ++i) {
    const Vec3f& n = loaded.map.texels[i];
    if (i % 3 == 0) {
      EXPECT_EQ(n.z(), 0.0f) << i;
      const Vec3 horizon = Vec3(std::cos(float(i)), std::sin(float(i)), 0.0);
      EXPECT_LT((n.cast<double>() - horizon).norm(), 1e-6) << i;
    }
  }
  expect_both_bakes_exact(loaded.map, 6, 3);
}

// Protects against: sin(theta) underflowing to 0 and phi = atan2(0, 0) at the pole for order 100 in f16, where a
// normal 1e-30 off the pole is the pole to double precision: every level must be Y_l0(+z) = sqrt((2l + 1) / 4 pi)
// with every m != 0 coefficient 0.
TEST(HardCases, FilteringOrder100WithNormalsAtThePole) {
  const NormalMap map =
      test::filled(4, 2, [](uint32_t x, uint32_t) { return x % 2 ? Vec3(0, 0, 1) : Vec3(1e-30, 0, 1); });
  const Asset a = bake_sh(map, 100, ShPrecision::f16);
  const std::vector<float> g = a.read_as_float("level_2");
  for (int l = 0; l <= 100; ++l)
    for (int m = -l; m <= l; ++m) {
      const double exact = m ? 0.0 : std::sqrt((2 * l + 1) / (4 * std::numbers::pi));
      ASSERT_NEAR(g[size_t(sh_index(l, m))], exact, std::abs(exact) / 2048 + 1e-7) << l << " " << m;
    }
}

}  // namespace
}  // namespace mbk
