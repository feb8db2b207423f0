// Hard cases of the evaluator's filtered lookups (libbake/eval/: uv_footprint.h, material_normals.h,
// filtered_ndf_textures.h; libbake/colormap/moment_pyramid.h): pixel footprints of 0, 1 and 10^6 texels handed to
// every filtered lookup (the plain MIP normal, the SH and vMF NDF textures read from their assets, the moments of a
// driver), and camera rays parallel to a plane. Expected values are computed here from the map itself: the texel's
// own value for a footprint of at most one texel at its centre, the whole map's statistics for 10^6 texels (past
// the coarsest level of a 48 x 40 map).
#include <gtest/gtest.h>

#include <cmath>

#include "libbake/colormap/moment_pyramid.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/eval/camera_rays.h"
#include "libbake/eval/filtered_ndf_textures.h"
#include "libbake/eval/material_normals.h"
#include "libbake/eval/shape_intersection.h"
#include "libbake/eval/uv_footprint.h"
#include "tests/hard_cases/filter_assets.h"
#include "tests/hard_cases/hard_case_checks.h"

namespace mbk {
namespace {

constexpr uint32_t W = 48, H = 40;
constexpr int kOrder = 6, kLobes = 3;

// Every filtered lookup of one map, and a driver made of its x components.
struct Lookups {
  NormalMap map = test::random_normal_map(W, H, 12);
  MaterialNormals mip{NormalFilter::trilinear, std::make_shared<NormalPyramid>(build_normal_pyramid(map))};
  ShNdfTexture sh = ShNdfTexture::from_asset(test::bake_sh(map, kOrder, ShPrecision::f32));
  VmfTexture vmf = VmfTexture::from_asset(test::bake_vmf(map, kLobes, 0.0));
  Driver driver = [this] {
    Driver d;
    d.width = W, d.height = H;
    for (const Vec3f& n : map.texels) d.values.push_back(n.x());
    return d;
  }();
  MomentPyramid moments = build_moment_pyramid(driver);
};
const Lookups& lookups() {
  static const Lookups l;
  return l;
}

// A square footprint of side texels (its area side^2 texels).
UvFootprint square_footprint(double side) {
  UvFootprint f;
  f.duv_dx = Vec2(side / W, 0.0);
  f.duv_dy = Vec2(0.0, side / H);
  return f;
}

// The level of detail of a footprint's probes (footprint_probes; with max_probes 1, one isotropic probe at
// log2 of the ellipse's major axis in texels). Every footprint here is round or checked isotropically.
double lookup_lod(UvFootprint f, uint32_t w, uint32_t h, int max_probes = UvFootprint{}.max_probes) {
  f.max_probes = max_probes;
  const FootprintProbes probes = footprint_probes(Vec2(0.5, 0.5), f, w, h);
  EXPECT_EQ(probes.size(), 1);
  return probes.begin()->lod;
}

// uv of the centre of texel (x, row): u = (x + 1/2) / W, v = 1 - (row + 1/2) / H (normal_map.h).
Vec2 texel_centre(uint32_t x, uint32_t row) { return Vec2((x + 0.5) / W, 1.0 - (row + 0.5) / H); }

// At most one texel under the footprint, at a texel centre: every lookup returns that texel's own value.
void expect_texel_values(double side) {
  const Lookups& l = lookups();
  const UvFootprint f = square_footprint(side);
  const double lod = lookup_lod(f, W, H);
  ASSERT_EQ(lod, 0.0);
  std::vector<double> g(size_t(sh_count(kOrder)));
  for (const auto& [x, row] : {std::pair{0u, 0u}, {17u, 23u}, {W - 1, H - 1}}) {
    const Vec2 uv = texel_centre(x, row);
    const Vec3 n = l.map.at(x, row).cast<double>();
    EXPECT_LT((l.mip.lookup(uv, f) - n.normalized()).norm(), 1e-6);
    l.sh.lookup(uv, lod, g);
    for (int k = 0, lm = 0; k <= kOrder; ++k)
      for (int m = -k; m <= k; ++m, ++lm) EXPECT_NEAR(g[size_t(lm)], test::independent_sh(k, m, n), 1e-6) << k << m;
    const std::vector<VmfLobeShape> lobes = l.vmf.lookup(uv, lod);
    ASSERT_EQ(lobes.size(), size_t(kLobes) + 1);  // below LOD 1: J + 1 lobes, level 0's delta the only one here
    EXPECT_EQ(lobes.front().alpha, 1.0);
    EXPECT_EQ(lobes.front().kappa, kVmfKappaMax);
    EXPECT_LT((lobes.front().mu - n.normalized()).norm(), 1e-6);
    for (size_t j = 1; j < lobes.size(); ++j) EXPECT_EQ(lobes[j].alpha, 0.0);
    const FootprintMoments m = sample_moments(l.moments, uv, lod);
    EXPECT_NEAR(m.mean, n.x(), 1e-7);
    EXPECT_NEAR(m.variance, 0.0, 1e-7);
  }
}

// Protects against: a zero footprint (duv = 0, a degenerate differential): log2(0) = -inf must become LOD 0, not NaN
// or a negative level index.
TEST(HardCases, FootprintOfZeroTexels) { expect_texel_values(0.0); }

// Protects against: the magnification boundary: a footprint of one texel is LOD 0, and so is one of sqrt(3) texels
// (the width whose box variance a level-0 lookup matches, uv_footprint.h); one a hair larger (LOD 1.4e-9) must give
// the same lookups within 1e-6 (no jump between the level-0 path and the blended one).
TEST(HardCases, FootprintOfOneTexel) {
  expect_texel_values(1.0);
  const Lookups& l = lookups();
  const UvFootprint one = square_footprint(std::sqrt(3.0)), more = square_footprint(std::sqrt(3.0) * (1.0 + 1e-9));
  EXPECT_LT(lookup_lod(one, W, H), 1e-12);
  const double lod = lookup_lod(more, W, H);
  EXPECT_GT(lod, 0.0);
  EXPECT_LT(lod, 1e-8);
  const Vec2 uv(0.3141, 0.2718);
  EXPECT_LT((l.mip.lookup(uv, one) - l.mip.lookup(uv, more)).norm(), 1e-6);
  std::vector<double> a(size_t(sh_count(kOrder))), b(a.size());
  l.sh.lookup(uv, 0.0, a);
  l.sh.lookup(uv, lod, b);
  for (size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-6) << k;
  Vec3 first_a = Vec3::Zero(), first_b = Vec3::Zero();  // the mixtures' first moments
  for (const VmfLobeShape& s : l.vmf.lookup(uv, 0.0)) first_a += s.alpha * vmf_mean_length(s.kappa) * s.mu;
  for (const VmfLobeShape& s : l.vmf.lookup(uv, lod)) first_b += s.alpha * vmf_mean_length(s.kappa) * s.mu;
  EXPECT_LT((first_a - first_b).norm(), 1e-6);
  EXPECT_NEAR(sample_moments(l.moments, uv, 0.0).variance, sample_moments(l.moments, uv, lod).variance, 1e-7);
}

// Protects against: footprints far larger than the map (10^6 texels on a 48 x 40 map: LOD 9.97 against 6 levels):
// the LOD must clamp to the coarsest level, which holds the whole map's NDF, wherever the pixel is.
TEST(HardCases, FootprintOfAMillionTexels) {
  const Lookups& l = lookups();
  const UvFootprint f = square_footprint(1000.0);
  const double lod = lookup_lod(f, W, H);
  EXPECT_NEAR(lod, std::log2(1000.0) - kLodOfBoxVariance, 1e-12);
  Vec3 mean = Vec3::Zero();
  double driver_mean = 0.0, driver_square = 0.0;
  std::vector<double> exact(size_t(sh_count(kOrder)), 0.0);
  for (const Vec3f& nf : l.map.texels) {
    const Vec3 n = nf.cast<double>();
    mean += n / double(W * H);
    driver_mean += n.x() / double(W * H), driver_square += n.x() * n.x() / double(W * H);
    for (int k = 0, lm = 0; k <= kOrder; ++k)
      for (int m = -k; m <= k; ++m, ++lm) exact[size_t(lm)] += test::independent_sh(k, m, n) / double(W * H);
  }
  std::vector<double> g(exact.size());
  for (const Vec2& uv : {Vec2(0.0, 0.0), Vec2(0.37, 0.81), Vec2(-3.2, 7.9)}) {
    EXPECT_LT((l.mip.lookup(uv, f) - mean.normalized()).norm(), 1e-6);
    l.sh.lookup(uv, lod, g);
    for (size_t k = 0; k < g.size(); ++k) EXPECT_NEAR(g[k], exact[k], 1e-6) << k;
    Vec3 first = Vec3::Zero();
    double mass = 0.0;
    for (const VmfLobeShape& s : l.vmf.lookup(uv, lod)) {
      mass += s.alpha;
      first += s.alpha * vmf_mean_length(s.kappa) * s.mu;
    }
    EXPECT_NEAR(mass, 1.0, 1e-6);
    EXPECT_LT((first - mean).norm(), 2e-6);
    const FootprintMoments m = sample_moments(l.moments, uv, lod);
    EXPECT_NEAR(m.mean, driver_mean, 1e-7);
    EXPECT_NEAR(m.variance, driver_square - driver_mean * driver_mean, 1e-7);
  }
}

// Protects against: rays parallel to a plane (D . n = 0: t = -(o - c) . n / 0) reporting a hit at +-inf or NaN, and
// rays grazing it by eps, whose footprint must follow the closed form: with the ray differential turning the
// direction by delta towards the normal, the hit moves by t delta / sin(eps) along the ray's azimuth (Igehy's
// transfer), up to eps = 1e-12 where D . n is 1e-12.
TEST(HardCases, CameraRayParallelToThePlane) {
  Shape plane;
  plane.normal = Vec3::UnitZ();
  plane.tangent = Vec3::UnitX();
  plane.size = Vec2(2.0, 2.0);
  EXPECT_FALSE(intersect_shape(plane, Ray{Vec3(-0.9, 0.1, 0.25), Vec3::UnitX()}, INFINITY));
  EXPECT_FALSE(intersect_shape(plane, Ray{Vec3(-0.9, 0.1, 0.0), Vec3::UnitX()}, INFINITY));  // in the plane
  EXPECT_FALSE(intersect_shape(plane, Ray{Vec3(-0.9, 0.1, -0.0), Vec3(0.6, 0.8, 0.0)}, INFINITY));
  const double delta = 1e-3;
  double previous_lod = 0.0;
  for (const double eps : {1e-2, 1e-4, 1e-6, 1e-9, 1e-12}) {
    const Vec3 D(std::cos(eps), 0.0, -std::sin(eps));
    const double t = 1.5;
    RayDifferential r{Ray{Vec3(-0.9, 0.2, 0.0) - t * D, D}, Vec3(0.0, delta, 0.0),
                      delta * Vec3(std::sin(eps), 0.0, std::cos(eps))};
    const auto hit = intersect_shape(plane, r.ray, INFINITY);
    ASSERT_TRUE(hit) << eps;
    EXPECT_NEAR(hit->t, t, 1e-9 * t);
    const UvFootprint f = uv_footprint(*hit, r);
    // dp/dy = t delta (1 / sin(eps), 0, 0); u spans the plane's 2 units, so du/dy = t delta / (2 sin(eps)).
    const double expected = t * delta / (2 * std::sin(eps));
    EXPECT_NEAR(f.duv_dy.x(), expected, 1e-6 * expected) << eps;
    EXPECT_NEAR(f.duv_dx.y(), t * delta / 2, 1e-9) << eps;
    const double lod = lookup_lod(f, 512, 512, 1);
    EXPECT_NEAR(lod, std::log2(expected * 512) - kLodOfBoxVariance, 1e-6) << eps;
    EXPECT_GT(lod, previous_lod);
    previous_lod = lod;
  }
  // Through a pinhole at the plane's height, looking along it: the middle row's rays are parallel and miss; the
  // row below hits far away at a grazing angle with a finite footprint.
  Camera camera{Vec3(-0.99, 0.0, 1e-6), Vec3(1.0, 0.0, 1e-6), Vec3::UnitZ(), 30.0, 9, 9};
  const PinholeCamera pinhole(camera);
  EXPECT_FALSE(intersect_shape(plane, pinhole.ray(4.5, 4.5).ray, INFINITY));
  const RayDifferential below = pinhole.ray(4.5, 4.5 + 1e-4);
  const auto hit = intersect_shape(plane, below.ray, INFINITY);
  ASSERT_TRUE(hit);
  const double lod = lookup_lod(uv_footprint(*hit, below), 512, 512, 1);
  EXPECT_TRUE(std::isfinite(lod));
  EXPECT_GT(lod, 0.0);
}

}  // namespace
}  // namespace mbk
