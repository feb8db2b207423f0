// What the reconstruction buys against bilinear interpolation on the `panels` map, whose exact surface normal is
// known (panel_normal) and whose exact crease lines are the curves: angular error against the truth at
// magnifications 1x to 64x (m x m points per texel over a 16 x 16 texel window). Asserts that the
// reconstruction is better wherever magnification resolves the creases, and records the figures
// (gtest --gtest_output=json) for scripts/bench-crease.sh, which writes examples/results/crease/REPORT.md.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>

#include "formats/crease_reconstruction.h"
#include "libbake/gen/panels.h"
#include "tests/crease/crease_test_maps.h"

namespace mbk {
namespace {

struct ErrorFigures {
  double rms_degrees = 0.0, p99_degrees = 0.0, above_10_degrees = 0.0;  // fraction of points
};

ErrorFigures figures(std::vector<double> angles) {
  ErrorFigures f;
  double sum = 0.0;
  uint64_t above = 0;
  for (double a : angles) sum += a * a, above += a > 10.0;
  f.rms_degrees = std::sqrt(sum / double(angles.size()));
  f.above_10_degrees = double(above) / double(angles.size());
  std::sort(angles.begin(), angles.end());
  f.p99_degrees = angles[size_t(0.99 * double(angles.size() - 1))];
  return f;
}

double angle_degrees(const double n[3], const Vec3& exact) {
  const double c = std::clamp(n[0] * exact.x() + n[1] * exact.y() + n[2] * exact.z(), -1.0, 1.0);
  return std::acos(c) * 180.0 / M_PI;
}

// The error of n at p against the surface: on a crease line (within 1e-9 texels: the 45-degree mitres run through
// points of the m x m grids) the surface has the normals of the facets on both sides and either is right; elsewhere
// its one normal. `near` holds the creases that may pass through the measured window.
double error_degrees(const double n[3], const PanelLayout& layout, const std::vector<CreaseSegment>& near,
                     const Vec2& offset, const Vec2& p) {
  double error = angle_degrees(n, panel_normal(layout, p + offset));
  for (const CreaseSegment& s : near) {
    const Vec2 d = s.b - s.a;
    const double t = std::clamp((p - s.a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    if ((s.a + t * d - p).norm() > 1e-9) continue;
    const Vec2 across = Vec2(-d.y(), d.x()).normalized() * 1e-6;
    for (const Vec2& q : std::array<Vec2, 2>{p + across, p - across})
      error = std::min(error, angle_degrees(n, panel_normal(layout, q + offset)));
  }
  return error;
}

// Two inputs: "gen", the map `microbake gen panels` writes (central differences of the height: texels within a
// texel of a crease mix both sides), and "exact", the exact normals point-sampled at the texel centres (each
// sample on one side: what [Parilov05] assumes the map holds).
// "shifted": the exact normals of the same surface moved by `offset` texels, curves with it, so that no crease runs
// through a texel centre and no panel corner sits on a cell's centre (the layout in general position).
void measure(const std::string& input, bool point_sampled, const Vec2& offset = Vec2::Zero()) {
  const MapSize size{256, 256};
  const uint32_t seed = 1;
  const PanelLayout layout = panel_layout(size, seed);
  CurveSet curves;
  std::vector<CreaseSegment> near;  // the creases whose bounding box meets the window [8, 24)^2
  for (CreaseSegment s : panel_creases(layout)) {
    s.a -= offset, s.b -= offset;
    curves.curves.push_back({{s.a, s.b}, false, "panels"});
    if (std::max(s.a.x(), s.b.x()) >= 8 && std::min(s.a.x(), s.b.x()) <= 24 && std::max(s.a.y(), s.b.y()) >= 8 &&
        std::min(s.a.y(), s.b.y()) <= 24)
      near.push_back(s);
  }
  const NormalMap map = point_sampled ? test::map_from(size.width, size.height,
                                                       [&](const Vec2& p) { return panel_normal(layout, p + offset); })
                                      : generate_panels(size, seed, Progress::silent());
  const BakedCrease baked = test::bake(map, curves);
  CreaseProfile none;  // b = 1 everywhere: the map's own normals, interpolated side-aware
  none.blend_start = none.blend_end = 0.0;
  for (uint32_t m : {1u, 2u, 4u, 8u, 16u, 32u, 64u}) {
    std::vector<double> bilinear, crease;
    double bilinear_seconds = 0.0, crease_seconds = 0.0;
    for (uint32_t ty = 8; ty < 24; ++ty)
      for (uint32_t tx = 8; tx < 24; ++tx) {
        std::vector<Vec2> points;
        for (uint32_t b = 0; b < m; ++b)
          for (uint32_t a = 0; a < m; ++a) points.emplace_back(tx + (a + 0.5) / m, ty + (b + 0.5) / m);
        std::vector<double> nb(3 * points.size()), nc(3 * points.size());
        auto t0 = std::chrono::steady_clock::now();
        for (size_t k = 0; k < points.size(); ++k)
          bilinear_normal(baked.field, points[k].x(), points[k].y(), &nb[3 * k]);
        auto t1 = std::chrono::steady_clock::now();
        for (size_t k = 0; k < points.size(); ++k)
          crease_normal(reconstruct_crease(baked.field, points[k].x(), points[k].y()), none, &nc[3 * k]);
        auto t2 = std::chrono::steady_clock::now();
        bilinear_seconds += std::chrono::duration<double>(t1 - t0).count();
        crease_seconds += std::chrono::duration<double>(t2 - t1).count();
        for (size_t k = 0; k < points.size(); ++k) {
          bilinear.push_back(error_degrees(&nb[3 * k], layout, near, offset, points[k]));
          crease.push_back(error_degrees(&nc[3 * k], layout, near, offset, points[k]));
        }
      }
    const ErrorFigures fb = figures(bilinear), fc = figures(crease);
    const std::string key = input + "_m" + std::to_string(m) + "_";
    ::testing::Test::RecordProperty(key + "points", std::to_string(bilinear.size()));
    ::testing::Test::RecordProperty(key + "bilinear_rms_deg", std::to_string(fb.rms_degrees));
    ::testing::Test::RecordProperty(key + "bilinear_p99_deg", std::to_string(fb.p99_degrees));
    ::testing::Test::RecordProperty(key + "bilinear_above10", std::to_string(fb.above_10_degrees));
    ::testing::Test::RecordProperty(key + "crease_rms_deg", std::to_string(fc.rms_degrees));
    ::testing::Test::RecordProperty(key + "crease_p99_deg", std::to_string(fc.p99_degrees));
    ::testing::Test::RecordProperty(key + "crease_above10", std::to_string(fc.above_10_degrees));
    // Evaluation cost, recorded for the benchmark (not asserted: timing belongs to benchmarks).
    ::testing::Test::RecordProperty(key + "bilinear_ns",
                                    std::to_string(1e9 * bilinear_seconds / double(bilinear.size())));
    ::testing::Test::RecordProperty(key + "crease_ns", std::to_string(1e9 * crease_seconds / double(crease.size())));
    if (m >= 4) {
      EXPECT_LT(fc.rms_degrees, fb.rms_degrees) << "magnification " << m;
      EXPECT_LT(fc.above_10_degrees, fb.above_10_degrees) << "magnification " << m;
    }
    // With samples that each hold one side's normal, the reconstruction is exact on the planar facets but
    // for the cells the simplification changed (merged crossings, deleted segments).
    if (point_sampled && m >= 4) {
      EXPECT_LT(fc.above_10_degrees, 0.5 * fb.above_10_degrees) << "magnification " << m;
    }
    // Issue 12's goal, half of the 5.9 degrees RMS and 45 degrees p99 measured before samples on a crease were kept
    // out of both sides and junction cells existed: what is left is the cells where a crease ends at a sample.
    if (point_sampled && m >= 8) {
      EXPECT_LT(fc.rms_degrees, 2.95) << input << ", magnification " << m;
      EXPECT_LT(fc.p99_degrees, 22.5) << input << ", magnification " << m;
    }
  }
}

TEST(CreaseAccuracy, ReconstructionBeatsBilinearOnPanels) {
  measure("gen", false);
  measure("exact", true);
  measure("shifted", true, Vec2(0.31, 0.17));
}

}  // namespace
}  // namespace mbk
