// Hard cases of the crease bake (libbake/crease/crease_asset.h), by name: 1 x 1 and non-square maps, curves on
// the lattice and through samples, a curve that crosses no cell, constant maps, normals at the horizon on both
// sides of a crease, option limits, and thread-count independence.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/crease_reconstruction.h"
#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "tests/crease/crease_test_maps.h"

namespace mbk {
namespace {

void expect_finite(const CreaseField& f, uint32_t w, uint32_t h) {
  for (double y = 0.0; y <= h; y += 0.125)
    for (double x = 0.0; x <= w; x += 0.125) {
      const CreaseSample s = reconstruct_crease(f, x, y);
      ASSERT_TRUE(std::isfinite(s.distance) && s.distance >= 0.0) << x << "," << y;
      ASSERT_NEAR(std::hypot(s.gradient[0], s.gradient[1]), 1.0, 1e-9) << x << "," << y;
      ASSERT_NEAR(std::sqrt(s.normal[0] * s.normal[0] + s.normal[1] * s.normal[1] + s.normal[2] * s.normal[2]), 1.0,
                  1e-9);
    }
}

TEST(CreaseBake, OneByOneMap) {
  const BakedCrease b = test::bake(test::flat_map(1, 1), test::curves_of({{{0.0, 0.0}, {1.0, 1.0}}}));
  EXPECT_GT(b.network_segments, 0u);
  expect_finite(b.field, 1, 1);
}

TEST(CreaseBake, NonSquareNonPowerOfTwo) {
  const BakedCrease b = test::bake(test::flat_map(37, 5), test::curves_of({{{0.0, 4.9}, {37.0, 0.3}}}));
  expect_finite(b.field, 37, 5);
}

TEST(CreaseBake, CurveThroughSamplesAndAlongLatticeLines) {
  CurveSet c;
  c.curves.push_back({{{3.5, 0.0}, {3.5, 8.0}}, false, "through texel centres (samples)"});
  c.curves.push_back({{{0.0, 4.0}, {8.0, 4.0}}, false, "along a lattice line"});
  c.curves.push_back({{{0.5, 0.5}, {7.5, 7.5}}, false, "through lattice vertices"});
  const BakedCrease b = test::bake(test::flat_map(8, 8), c);
  expect_finite(b.field, 8, 8);
  // The samples on the first curve are within the clamped crossing offset (1/1024 texel) of the network.
  for (uint32_t j = 1; j <= 8; ++j) EXPECT_LE(b.field.distance[b.field.sample_index(4, j)], 1.5f / 1024.0f) << j;
}

TEST(CreaseBake, CurveCrossingNoCellIsAnError) {
  try {
    test::bake(test::flat_map(4, 4), test::curves_of({{{1.6, 1.6}, {2.4, 2.4}}}));
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(std::string(e.what()).find("nothing to bake"), std::string::npos);
  }
}

TEST(CreaseBake, OptionLimits) {
  const CurveSet c = test::curves_of({{{0.0, 0.0}, {4.0, 4.0}}});
  EXPECT_THROW(test::bake(test::flat_map(4, 4), c, 10, 0.0), Error);
  EXPECT_THROW(test::bake(test::flat_map(4, 4), c, 10, std::nan("")), Error);
  EXPECT_THROW(test::bake(test::flat_map(4, 4), c, kCreaseMaxSmoothIterations + 1), Error);
  EXPECT_NO_THROW(test::bake(test::flat_map(4, 4), c, 0, 1e-6));
}

TEST(CreaseBake, ConstantMapReconstructsTheConstant) {
  const NormalMap map = test::map_from(12, 9, [](const Vec2&) { return Vec3(0.3, -0.2, 0.9); });
  const BakedCrease b = test::bake(map, test::curves_of({{{0.0, 1.3}, {12.0, 8.2}}, {{2.2, 9.0}, {9.7, 0.0}}}));
  const Vec3 n = Vec3(0.3, -0.2, 0.9).normalized();
  for (double y = 0.05; y < 9.0; y += 0.1)
    for (double x = 0.05; x < 12.0; x += 0.1) {
      const CreaseSample s = reconstruct_crease(b.field, x, y);
      EXPECT_NEAR(s.normal[0], n.x(), 1e-6);
      EXPECT_NEAR(s.normal[1], n.y(), 1e-6);
      EXPECT_NEAR(s.normal[2], n.z(), 1e-6);
    }
}

TEST(CreaseBake, HorizonNormalsOnOppositeSides) {
  // Normals at the horizon pointing apart: bilinear interpolation cancels them to a zero vector in the middle
  // of a cell; the reconstruction keeps each side's normal.
  const Vec2 a(5.37, 0.0), b(5.37, 8.0);
  const NormalMap map = test::map_from(10, 8, [&](const Vec2& p) { return Vec3(p.x() < 5.37 ? -1.0 : 1.0, 0, 0); });
  const BakedCrease baked = test::bake(map, test::curves_of({{a, b}}));
  expect_finite(baked.field, 10, 8);
  for (double y = 0.6; y < 7.5; y += 0.1) {
    EXPECT_NEAR(reconstruct_crease(baked.field, 5.2, y).normal[0], -1.0, 1e-9);
    EXPECT_NEAR(reconstruct_crease(baked.field, 5.5, y).normal[0], 1.0, 1e-9);
  }
}

TEST(CreaseBake, SameFieldWhateverTheThreadCount) {
  CurveSet c;
  c.curves.push_back({{{0.3, 0.2}, {30.7, 19.1}, {3.1, 19.8}}, true, "test"});
  const NormalMap map = test::map_from(31, 20, [](const Vec2& p) { return Vec3(std::sin(p.x()), std::cos(p.y()), 2); });
  set_thread_count(1);
  const BakedCrease one = test::bake(map, c);
  set_thread_count(2);
  const BakedCrease two = test::bake(map, c);
  set_thread_count(0);
  EXPECT_EQ(one.field.gradient, two.field.gradient);
  EXPECT_EQ(one.field.distance, two.field.distance);
  EXPECT_EQ(one.field.segments, two.field.segments);
}

}  // namespace
}  // namespace mbk
