// The procedural generators: deterministic (same seed -> identical texels, whatever the thread count;
// another seed -> another map), unit length and above the horizon, any size from 1 x 1 (non-square,
// non-power-of-two), tileable, and integrable when derived from a height field (curl of the slope field
// ~ 0, against ~ 1 for the flakes, which are not a height field).
#include <gtest/gtest.h>

#include <cmath>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/gen/generator.h"
#include "libbake/gen/height_field.h"
#include "libbake/gen/periodic_noise.h"
#include "libbake/image/convention_detection.h"

namespace mbk {
namespace {

NormalMap gen(const GeneratorKind& k, MapSize size, uint32_t seed) {
  return k.generate(size, seed, Progress::silent());
}

std::string kind_name(const ::testing::TestParamInfo<GeneratorKind>& info) { return std::string(info.param.name); }

class Generators : public ::testing::TestWithParam<GeneratorKind> {};

TEST_P(Generators, SameSeedGivesIdenticalMapsWhateverTheThreadCount) {
  const int threads = thread_count();
  set_thread_count(1);
  const NormalMap one = gen(GetParam(), {96, 64}, 5);
  set_thread_count(2);
  const NormalMap two = gen(GetParam(), {96, 64}, 5);
  set_thread_count(threads);
  EXPECT_EQ(one.texels, two.texels);
}

TEST_P(Generators, DifferentSeedsGiveDifferentMaps) {
  const NormalMap a = gen(GetParam(), {64, 64}, 1), b = gen(GetParam(), {64, 64}, 2);
  size_t differing = 0;
  for (size_t i = 0; i < a.texels.size(); ++i) differing += a.texels[i] != b.texels[i];
  EXPECT_GT(differing, a.texels.size() / 20);
}

TEST_P(Generators, UnitLengthAboveTheHorizonAtAnySize) {
  for (MapSize size : {MapSize{1, 1}, MapSize{2, 2}, MapSize{3, 5}, MapSize{37, 20}, MapSize{20, 37}, MapSize{257, 3},
                       MapSize{128, 128}}) {
    const NormalMap m = gen(GetParam(), size, 9);
    ASSERT_EQ(m.width, size.width);
    ASSERT_EQ(m.height, size.height);
    ASSERT_EQ(m.texels.size(), size_t(size.width) * size.height);
    for (const Vec3f& n : m.texels) {
      ASSERT_TRUE(n.allFinite());
      EXPECT_NEAR(n.norm(), 1.0f, 1e-6f);
      EXPECT_GT(n.z(), 0.5f);  // no generator tilts beyond 60 degrees
    }
  }
}

TEST_P(Generators, MapsAreNotFlat) {
  const NormalMap m = gen(GetParam(), {128, 96}, 4);
  double mean_tilt = 0;
  for (const Vec3f& n : m.texels) mean_tilt += std::acos(std::min(1.0f, n.z()));
  mean_tilt /= double(m.texels.size());
  EXPECT_GT(mean_tilt, 0.01) << "mean tilt in radians";
}

// Tiling: the wrap-around seam is no sharper than the sharpest column (row) boundary inside the map. A map
// that did not tile would show a jump between unrelated texels there; a panel grid has a groove at the
// seam just like at its inner grid lines.
TEST_P(Generators, MapsTileSeamlessly) {
  const NormalMap m = gen(GetParam(), {160, 120}, 6);
  auto column_step = [&](uint32_t a, uint32_t b) {
    double s = 0;
    for (uint32_t r = 0; r < m.height; ++r) s += (m.at(b, r) - m.at(a, r)).norm();
    return s;
  };
  auto row_step = [&](uint32_t a, uint32_t b) {
    double s = 0;
    for (uint32_t x = 0; x < m.width; ++x) s += (m.at(x, b) - m.at(x, a)).norm();
    return s;
  };
  double inner_x = 0, inner_y = 0;
  for (uint32_t x = 0; x + 1 < m.width; ++x) inner_x = std::max(inner_x, column_step(x, x + 1));
  for (uint32_t r = 0; r + 1 < m.height; ++r) inner_y = std::max(inner_y, row_step(r, r + 1));
  EXPECT_LE(column_step(m.width - 1, 0), inner_x + 1e-9);
  EXPECT_LE(row_step(m.height - 1, 0), inner_y + 1e-9);
}

TEST_P(Generators, HeightDerivedMapsAreIntegrable) {
  // The curl statistic s of libbake/image/convention_detection.h: 1 - s is the curl energy of the slope field
  // relative to the energy of the two terms that must cancel (the square of the relative RMS curl).
  const NormalMap m = gen(GetParam(), {128, 80}, 3);
  const double s = measure_convention(m).statistic;
  if (GetParam().from_height) {
    EXPECT_LT(1.0 - s, 1e-10) << "curl energy of the slope field relative to its terms";
    // ... and only in the +Y convention they are written in: flipping y breaks integrability.
    NormalMap flipped = m;
    for (Vec3f& n : flipped.texels) n.y() = -n.y();
    EXPECT_GT(1.0 - measure_convention(flipped).statistic, 1.9);
  } else {
    EXPECT_GT(1.0 - s, 0.5) << "flakes are independent facets, not a height field";
  }
}

INSTANTIATE_TEST_SUITE_P(AllKinds, Generators, ::testing::ValuesIn(generator_kinds().begin(), generator_kinds().end()),
                         kind_name);

TEST(GeneratorRegistry, KnowsTheSixKindsAndRefusesOthers) {
  EXPECT_EQ(generator_names(), "bumps, brushed, scratches, flakes, leather, panels");
  EXPECT_EQ(find_generator("brushed")->generate, &generate_brushed);
  EXPECT_EQ(find_generator("nope"), nullptr);
  EXPECT_FALSE(find_generator("flakes")->from_height);
  try {
    generate_normal_map("nope", {8, 8}, 1, Progress::silent());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_command_line);
    EXPECT_NE(std::string(e.what()).find("bumps, brushed"), std::string::npos);
  }
  EXPECT_THROW(generate_normal_map("bumps", {0, 8}, 1, Progress::silent()), Error);
  EXPECT_THROW(generate_normal_map("bumps", {kMaxNormalMapSide + 1, 8}, 1, Progress::silent()), Error);
}

TEST(GeneratorLooks, BrushedStreaksRunAlongU) {
  // Anisotropy: slopes across the streaks (y) dominate slopes along them (x).
  const NormalMap m = generate_brushed({256, 256}, 1, Progress::silent());
  double sx = 0, sy = 0;
  for (const Vec3f& n : m.texels) sx += n.x() * n.x(), sy += n.y() * n.y();
  EXPECT_GT(sy, 10.0 * sx);
}

TEST(GeneratorLooks, ScratchesAreSparseOnAFlatSurface) {
  const NormalMap m = generate_scratches({256, 256}, 1, Progress::silent());
  size_t flat = 0;
  for (const Vec3f& n : m.texels) flat += n == Vec3f(0, 0, 1);
  EXPECT_GT(flat, m.texels.size() * 8 / 10);
  EXPECT_LT(flat, m.texels.size());
}

TEST(GeneratorLooks, FlakesArePiecewiseConstant) {
  // Most texels equal their right-hand neighbour: flat facets, with changes only at flake borders.
  const NormalMap m = generate_flakes({256, 256}, 1, Progress::silent());
  size_t same = 0, tilted = 0;
  for (uint32_t r = 0; r < m.height; ++r)
    for (uint32_t x = 0; x + 1 < m.width; ++x) same += m.at(x, r) == m.at(x + 1, r), tilted += m.at(x, r).z() < 0.9999f;
  EXPECT_GT(same, size_t(m.width - 1) * m.height * 7 / 10);
  EXPECT_GT(tilted, m.texels.size() / 3);  // dense flakes
}

TEST(HeightField, NormalsAreCentralDifferencesWithYUp) {
  // h = x^2 + 3 row on a 6 x 4 grid: interior slopes dh/dx = 2x, dh/dy = -3 (rows go down, y goes up).
  const HeightField f = sample_height_field(
      6, 4, [](uint32_t x, uint32_t r) { return double(x * x) + 3.0 * r; }, Progress::silent());
  const NormalMap m = normals_from_height(f, 0.5);
  for (uint32_t r = 1; r < 3; ++r)
    for (uint32_t x = 1; x < 5; ++x) {
      const Vec3 expected = Vec3(-0.5 * 2.0 * x, -0.5 * -3.0, 1.0).normalized();
      EXPECT_NEAR((m.at(x, r).cast<double>() - expected).norm(), 0.0, 1e-7) << x << ", " << r;
    }
  // h grows with the row, i.e. falls towards the top of the image: the surface faces up there (ny > 0).
  EXPECT_GT(m.at(2, 1).y(), 0.0f);
  // Borders wrap: at x = 0 the left neighbour is x = 5.
  const Vec3 wrap = Vec3(-0.5 * 0.5 * (1.0 - 25.0), -0.5 * -3.0, 1.0).normalized();
  EXPECT_NEAR((m.at(0, 1).cast<double>() - wrap).norm(), 0.0, 1e-7);
}

TEST(HeightField, RmsSlopeScalingHitsItsTarget) {
  const HeightField f = sample_height_field(
      64, 48, [](uint32_t x, uint32_t r) { return periodic_fbm(texel_uv(x, r, 64, 48), 4, 3, 3, 0.5, 11); },
      Progress::silent());
  const NormalMap m = normals_with_rms_slope(f, 0.3);
  double s2 = 0;
  for (const Vec3f& n : m.texels) s2 += (double(n.x()) * n.x() + double(n.y()) * n.y()) / (double(n.z()) * n.z());
  EXPECT_NEAR(std::sqrt(s2 / double(m.texels.size())), 0.3, 1e-5);
  // A constant field has no slope to scale: flat normals, no division by zero.
  const HeightField flat = sample_height_field(
      5, 5, [](uint32_t, uint32_t) { return 2.0; }, Progress::silent());
  for (const Vec3f& n : normals_with_rms_slope(flat, 0.3).texels) EXPECT_EQ(n, Vec3f(0, 0, 1));
}

TEST(PeriodicNoise, WrapsAfterItsPeriodAndVanishesAtLatticePoints) {
  for (double x : {0.0, 0.3, 2.75, 6.9})
    for (double y : {0.1, 1.5, 4.2}) {
      const double v = periodic_gradient_noise(x, y, 7, 5, 3);
      EXPECT_NEAR(periodic_gradient_noise(x + 7.0, y, 7, 5, 3), v, 1e-12);
      EXPECT_NEAR(periodic_gradient_noise(x, y - 5.0, 7, 5, 3), v, 1e-12);
      EXPECT_LE(std::abs(v), 1.0 + 1e-12);
    }
  EXPECT_EQ(periodic_gradient_noise(3.0, 2.0, 7, 5, 3), 0.0);
  EXPECT_NE(periodic_gradient_noise(3.5, 2.5, 7, 5, 3), periodic_gradient_noise(3.5, 2.5, 7, 5, 4));
  EXPECT_EQ(octaves_resolved(8, 512, 10), 6);  // 8, 16, ..., 256 cells keep >= 2 texels per cell
  EXPECT_EQ(octaves_resolved(8, 4, 10), 1);
}

}  // namespace
}  // namespace mbk
