// uv to the glint target plane (libbake/glint/glint_surface_mapping.h): the v flip. The target's u_1 runs down
// the rows while tangent +v runs up, so the mapping flips v; the test that holds it is physical: a normal map
// derived from a height field is integrable, so in TANGENT space d n_x / dv = d n_y / du (both -d^2h/dudv, up to
// the normalisation of n). With the flip the point query's Jacobian mapped to uv is symmetric; without it the
// off-diagonal terms have opposite signs. Also: the mapping agrees with plain normal mapping's texel
// coordinates, and footprints from uv derivatives.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "libbake/core/progress.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/blended_normal.h"
#include "libbake/glint/glint_surface_mapping.h"

namespace mbk {
namespace {

TEST(GlintSurfaceMapping, PlusVMovesUpTheRowsLikePlainNormalMapping) {
  // uv (0, 1) is the example's top-left corner (row 0), uv (1, 0) its bottom-right, as in sample_bilinear.
  EXPECT_EQ(glint_target_point(Vec2(0, 1), 64, 32), Vec2(0, 0));
  EXPECT_EQ(glint_target_point(Vec2(1, 0), 64, 32), Vec2(64, 32));
  const Vec2 a = glint_target_point(Vec2(0.3, 0.4), 64, 32), b = glint_target_point(Vec2(0.3, 0.5), 64, 32);
  EXPECT_NEAR(b.y() - a.y(), -3.2, 1e-12);  // +v: up the rows
  EXPECT_NEAR(b.x() - a.x(), 0.0, 1e-12);
}

TEST(GlintSurfaceMapping, TangentJacobianOfAnIntegrableMapIsSymmetricOnlyWithTheFlip) {
  const NormalMap example = generate_normal_map("bumps", {128, 128}, 2, Progress::silent());
  const GlintPointQuery q(example, 64, 3, GlintBlendMode::none);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> uv(-20.0, 20.0);
  double sym_flip = 0.0, anti_flip = 0.0, sym_noflip = 0.0, anti_noflip = 0.0;
  for (int n = 0; n < 4000; ++n) {
    const Vec2 p(uv(rng), uv(rng));
    const Mat2 j = q.evaluate(glint_target_point(p, example.width, example.height)).jacobian;
    const Mat2 t = glint_tangent_jacobian(j, example.width, example.height);
    Mat2 wrong = j;  // the same without the flip: columns scaled by (W, +H)
    wrong.col(0) *= example.width;
    wrong.col(1) *= example.height;
    sym_flip += std::pow(t(0, 1) + t(1, 0), 2), anti_flip += std::pow(t(0, 1) - t(1, 0), 2);
    sym_noflip += std::pow(wrong(0, 1) + wrong(1, 0), 2), anti_noflip += std::pow(wrong(0, 1) - wrong(1, 0), 2);
  }
  // With the flip the antisymmetric part (the curl) is small against the symmetric one; without it, reversed.
  EXPECT_LT(anti_flip, 0.05 * sym_flip);
  EXPECT_LT(sym_noflip, 0.05 * anti_noflip);
}

TEST(GlintSurfaceMapping, ProbeFootprintIsTheBoxDeviationWithAFloor) {
  const GlintFootprint f = glint_probe_footprint(Vec2(0.5, 0.5), 10.0, 100, 100);
  EXPECT_EQ(f.center, Vec2(50, 50));
  EXPECT_NEAR(f.sigma, 10.0 / std::sqrt(12.0), 1e-12);  // a box of 10 texels
  EXPECT_EQ(glint_probe_footprint(Vec2(0, 0), 1e-4, 100, 100).sigma, kGlintMinFootprintSigma);
  EXPECT_FALSE(std::isfinite(glint_probe_footprint(Vec2(0, 0), INFINITY, 100, 100).sigma));
}

}  // namespace
}  // namespace mbk
