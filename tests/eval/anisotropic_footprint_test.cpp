// Anisotropic footprints (uv_footprint.h footprint_probes): the probes' geometry against the singular values of
// the footprint's Jacobian (Eigen's SVD, an independent computation), the degenerate cases (a circle is the
// isotropic lookup, grazing, magnification, the cap), and the property a user sees: on a plane seen at 80+
// degrees, the mean normal and the second moments of the footprint's normals - what the mip, toksvig, sh and
// vmf effects filter - match brute force over the texels the pixel covers (many sub-pixel rays through the raw
// map), where one isotropic lookup does not.
#include <gtest/gtest.h>

#include <iostream>

#include <Eigen/SVD>
#include <cmath>
#include <numbers>
#include <random>

#include "libbake/core/progress.h"
#include "libbake/eval/camera_rays.h"
#include "libbake/eval/shape_intersection.h"
#include "libbake/eval/uv_footprint.h"
#include "libbake/gen/generator.h"
#include "libbake/image/normal_pyramid.h"

namespace mbk {
namespace {

UvFootprint footprint_in_texels(const Vec2& a, const Vec2& b, uint32_t w, uint32_t h, int max_probes = 16) {
  UvFootprint f;
  f.duv_dx = a.cwiseQuotient(Vec2(w, h));
  f.duv_dy = b.cwiseQuotient(Vec2(w, h));
  f.max_probes = max_probes;
  return f;
}

TEST(FootprintProbes, CircleIsOneIsotropicLookup) {
  // Orthogonal columns of equal length rho at any rotation: one probe at uv of width rho (lod log2(rho) less the
  // box-variance offset, uv_footprint.h).
  for (double angle : {0.0, 0.3, 1.0, 2.5}) {
    const Vec2 a = 6.0 * Vec2(std::cos(angle), std::sin(angle)), b(-a.y(), a.x());
    const FootprintProbes p = footprint_probes(Vec2(0.3, 0.6), footprint_in_texels(a, b, 256, 128), 256, 128);
    ASSERT_EQ(p.size(), 1);
    EXPECT_EQ(p.begin()->uv, Vec2(0.3, 0.6));
    EXPECT_NEAR(p.begin()->lod, std::log2(6.0) - kLodOfBoxVariance, 1e-12);
  }
}

TEST(FootprintProbes, ProbesSpanTheMajorAxisOfTheSvd) {
  // Random Jacobians (sheared, rotated, any aspect): N = min(cap, ceil(s1 / s2), ceil(s1)) probes, equally
  // spaced along the major singular vector over its length s1, centred on uv, each of width max(s2, s1 / N).
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  const uint32_t W = 512, H = 256;
  int anisotropic = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Vec2 a(u(rng), u(rng)), b(u(rng) * 0.2, u(rng) * 0.2);
    Eigen::Matrix2d M;
    M << a.x(), b.x(), a.y(), b.y();
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(M, Eigen::ComputeFullU);
    const double s1 = svd.singularValues()(0), s2 = svd.singularValues()(1);
    const Vec2 u1 = svd.matrixU().col(0);
    const int cap = 1 + trial % 20;
    const FootprintProbes p = footprint_probes(Vec2(0.5, 0.5), footprint_in_texels(a, b, W, H, cap), W, H);
    if (s1 <= 1.0) {
      EXPECT_EQ(p.size(), 1);
      continue;
    }
    const int n = int(std::min({double(cap), std::ceil(s1 / s2 - 1e-9), std::ceil(s1)}));
    ASSERT_EQ(p.size(), n) << "s1 " << s1 << " s2 " << s2 << " cap " << cap;
    anisotropic += n > 1;
    Vec2 centroid = Vec2::Zero();
    for (int i = 0; i < n; ++i) {
      const FootprintProbe& probe = p.begin()[i];
      EXPECT_NEAR(probe.lod, std::max(0.0, std::log2(std::max(s2, s1 / n)) - kLodOfBoxVariance), 1e-9);
      const Vec2 offset = (probe.uv - Vec2(0.5, 0.5)).cwiseProduct(Vec2(W, H));  // in texels
      EXPECT_NEAR(std::abs(offset.dot(u1)), std::abs((i + 0.5) / n - 0.5) * s1, 1e-9 * s1);
      EXPECT_NEAR(offset.dot(Vec2(-u1.y(), u1.x())), 0.0, 1e-9 * s1);
      centroid += probe.uv / n;
    }
    EXPECT_NEAR((centroid - Vec2(0.5, 0.5)).norm(), 0.0, 1e-12);
  }
  EXPECT_GT(anisotropic, 300);
}

TEST(FootprintProbes, DegenerateFootprints) {
  // Grazing (infinite or NaN): one probe at the coarsest level. Magnification and zero: one at level 0. A
  // footprint thinner than a texel along its major axis never gets more probes than texels it spans; the cap is
  // clamped to [1, kMaxFootprintProbes].
  const auto probes = [](const Vec2& a, const Vec2& b, int cap = 16) {
    return footprint_probes(Vec2(0.2, 0.7), footprint_in_texels(a, b, 64, 64, cap), 64, 64);
  };
  for (const Vec2& bad : {Vec2(INFINITY, 0.0), Vec2(NAN, 1.0), Vec2(-INFINITY, INFINITY)}) {
    const FootprintProbes p = probes(bad, Vec2(0.0, 1.0));
    ASSERT_EQ(p.size(), 1);
    EXPECT_EQ(p.begin()->lod, kMaxLod);
  }
  for (const auto& [a, b] : {std::pair{Vec2(0.0, 0.0), Vec2(0.0, 0.0)}, std::pair{Vec2(0.9, 0.0), Vec2(0.0, 0.01)}}) {
    const FootprintProbes p = probes(a, b);
    ASSERT_EQ(p.size(), 1);
    EXPECT_EQ(p.begin()->lod, 0.0);
  }
  EXPECT_EQ(probes(Vec2(3.5, 0.0), Vec2(0.0, 0.001)).size(), 4);  // ceil(3.5) texels along the line
  EXPECT_EQ(probes(Vec2(1e6, 0.0), Vec2(0.0, 1.0), 0).size(), 1);
  EXPECT_EQ(probes(Vec2(1e6, 0.0), Vec2(0.0, 1.0), 1000).size(), kMaxFootprintProbes);
}

TEST(FootprintProbes, GrazingPlaneFootprintMatchesBruteForce) {
  // A 256^2 bumps map on a plane seen at 80 and 85 degrees: for every pixel of a row, the filtered mean normal
  // over the footprint (the mip lookup: the probes' trilinear means averaged) against the mean over 32 x 32
  // sub-pixel rays through the raw map (bilinear, as `render --reference`). The anisotropic lookup's error must be
  // well under the isotropic one's (which blurs over the major axis) and within a stated tolerance of the brute
  // force: 0.01 in the mean normal's tangential part, whose own size is 0.12-0.16 here. (A mip level's box is not
  // the pixel's parallelogram, so some error is inherent.) Measured: 0.0035 vs 0.045 isotropic at 80 degrees,
  // 0.0045 vs 0.061 at 85 (with lod = log2(width), not variance-matched: 0.0099 vs 0.076 and 0.0086 vs 0.086).
  const NormalMap map = generate_normal_map("bumps", {256, 256}, 3, Progress::silent());
  const NormalPyramid pyramid = build_normal_pyramid(map);
  Shape plane;  // z = 0, one tile of the map per scene unit
  plane.normal = Vec3::UnitZ();
  plane.tangent = Vec3::UnitX();
  plane.size = Vec2(100.0, 100.0);
  plane.uv_scale = Vec2(100.0, 100.0);
  const auto uv_of = [&](const RayDifferential& r) {
    const auto hit = intersect_shape(plane, r.ray, INFINITY);
    EXPECT_TRUE(hit);
    return hit ? hit->uv : Vec2(NAN, NAN);
  };
  for (double grazing : {80.0, 85.0}) {
    Camera c;
    const double theta = grazing * std::numbers::pi / 180;
    c.position = Vec3(0.0, -2.0 * std::sin(theta), 2.0 * std::cos(theta));
    c.look_at = Vec3::Zero();
    c.up = Vec3::UnitZ();
    c.fov_y_degrees = 20;
    c.width = 64;
    c.height = 48;
    const PinholeCamera camera(c);
    double err_aniso = 0.0, err_iso = 0.0, spread = 0.0;
    int pixels = 0;
    const uint32_t y = c.height / 2;
    for (uint32_t x = 0; x < c.width; ++x) {
      const RayDifferential centre = camera.ray(x + 0.5, y + 0.5);
      const auto hit = intersect_shape(plane, centre.ray, INFINITY);
      ASSERT_TRUE(hit);
      UvFootprint footprint = uv_footprint(*hit, centre);
      Vec3 truth = Vec3::Zero();
      const int n = 32;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          truth += sample_bilinear(map, uv_of(camera.ray(x + (i + 0.5) / n, y + (j + 0.5) / n))).normalized() / (n * n);
      footprint.max_probes = 16;
      Vec3 aniso = Vec3::Zero();
      const FootprintProbes probes = footprint_probes(hit->uv, footprint, map.width, map.height);
      for (const FootprintProbe& p : probes) aniso += sample_pyramid(pyramid, p.uv, p.lod) / probes.size();
      footprint.max_probes = 1;
      const FootprintProbes one = footprint_probes(hit->uv, footprint, map.width, map.height);
      const Vec3 iso = sample_pyramid(pyramid, one.begin()->uv, one.begin()->lod);
      EXPECT_GT(probes.size(), 3) << "at " << grazing << " degrees the footprint is elongated";
      err_aniso += (aniso - truth).head<2>().norm();
      err_iso += (iso - truth).head<2>().norm();
      spread += truth.head<2>().norm();
      ++pixels;
    }
    err_aniso /= pixels, err_iso /= pixels, spread /= pixels;
    std::cout << grazing << " degrees: mean |tangential error| anisotropic " << err_aniso << ", isotropic " << err_iso
              << " (mean |tangential mean| " << spread << ")\n";
    EXPECT_LT(err_aniso, 0.01);
    EXPECT_LT(err_aniso, 0.2 * err_iso);
  }
}

}  // namespace
}  // namespace mbk
