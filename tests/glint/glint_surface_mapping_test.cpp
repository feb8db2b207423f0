// uv to the glint target plane (libbake/glint/glint_surface_mapping.h): the v flip. The target's u_1 runs down
// the rows while tangent +v runs up, so the mapping flips v; the test that holds it is physical: a normal map
// derived from a height field is integrable, so in TANGENT space d n_x / dv = d n_y / du (both -d^2h/dudv, up to
// the normalisation of n). With the flip the point query's Jacobian mapped to uv is symmetric; without it the
// off-diagonal terms have opposite signs. Also: the mapping agrees with plain normal mapping's texel
// coordinates, footprints from uv derivatives, and the half vector's slope field K = ds/du (its hard cases).
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

// K = S M^-1 (glint_surface_mapping.h): where the probes cover just the pixel's image, moving across the pixel by
// one step moves s by the step's column of S (K M = S, M = diag(W, -H) [duv/dx duv/dy] written out here: the v
// flip); random pixels, stretched to 50:1 as at grazing angles.
TEST(GlintSurfaceMapping, SlopeFieldMovesTheHalfVectorByThePixelsSweep) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> v(-1.0, 1.0);
  const uint32_t W = 256, H = 128;
  for (int k = 0; k < 200; ++k) {
    const double angle = 3.14159 * v(rng), long_side = 20 + 80 * std::abs(v(rng)),
                 short_side = 2 + 20 * std::abs(v(rng));
    Mat2 m;  // target texels per pixel step: an ellipse at least 2 texels across
    m << long_side * std::cos(angle), -short_side * std::sin(angle), long_side * std::sin(angle),
        short_side * std::cos(angle);
    const Vec2 duv_dx(m(0, 0) / W, -m(1, 0) / H), duv_dy(m(0, 1) / W, -m(1, 1) / H);
    Mat2 steps;
    steps << 0.05 * v(rng), 0.05 * v(rng), 0.05 * v(rng), 0.05 * v(rng);
    const Mat2 slope = glint_half_vector_slope(steps, duv_dx, duv_dy, 0.5, W, H);  // probes narrower than the pixel
    EXPECT_LE((slope * m - steps).norm(), 1e-12 * steps.norm() + 1e-15) << k;
  }
}

// Hard cases: the probes reach further than the pixel's image (magnification under the 0.5-texel floor): s sweeps
// the pixel's own range over the footprint's box, K (sqrt(12) sigma_p R) = S for a pixel that is a scaled
// rotation R; an edge-on pixel (duv/dy = 0, M singular) keeps its x step and stays finite; a pixel of no extent,
// a non-finite footprint or sweep (grazing rays), and no sweep give K = 0.
TEST(GlintSurfaceMapping, SlopeFieldHardCases) {
  const uint32_t W = 64, H = 64;
  Mat2 steps;
  steps << 0.03, -0.01, 0.02, 0.04;
  const double c = std::cos(0.7), s = std::sin(0.7), scale = 0.1;  // 0.1 texel per pixel step
  const Vec2 duv_dx(scale * c / W, -scale * s / H), duv_dy(-scale * s / W, -scale * c / H);
  Mat2 rotation;
  rotation << c, -s, s, c;
  const double box = std::sqrt(12.0) * 0.5;
  const Mat2 slope = glint_half_vector_slope(steps, duv_dx, duv_dy, 0.5, W, H);
  EXPECT_LE((slope * box * rotation - steps).norm(), 1e-12);
  // Edge-on: M = [(8, 0), (0, 0)] texels; the x step is kept, nothing is infinite.
  const Mat2 edge = glint_half_vector_slope(steps, Vec2(8.0 / W, 0), Vec2(0, 0), 0.5, W, H);
  ASSERT_TRUE(edge.allFinite());
  EXPECT_LE((edge * Vec2(8, 0) - steps.col(0)).norm(), 1e-12);
  EXPECT_LE(edge.norm(), steps.norm() / box + steps.col(0).norm() / 8 + 1e-12);
  EXPECT_EQ(glint_half_vector_slope(steps, Vec2(0, 0), Vec2(0, 0), 0.5, W, H), Mat2::Zero());
  EXPECT_EQ(glint_half_vector_slope(steps, Vec2(INFINITY, 0), Vec2(0, 1), 0.5, W, H), Mat2::Zero());
  EXPECT_EQ(glint_half_vector_slope(steps, Vec2(0.1, 0), Vec2(0, 0.1), INFINITY, W, H), Mat2::Zero());
  Mat2 grazing = steps;
  grazing(0, 1) = NAN;
  EXPECT_EQ(glint_half_vector_slope(grazing, Vec2(0.1, 0), Vec2(0, 0.1), 0.5, W, H), Mat2::Zero());
  EXPECT_EQ(glint_half_vector_slope(Mat2::Zero(), Vec2(0.1, 0), Vec2(0, 0.1), 0.5, W, H), Mat2::Zero());
}

}  // namespace
}  // namespace mbk
