// Per-point reconstruction ([Parilov05] Sec. 4.3, appendix A; formats/crease_reconstruction.h): the proofs of
// issue 5 - the distance vanishes on every segment at sub-texel points, no information crosses a
// discontinuity (1,000 random points per cell), continuity away from features - and Eq. (1) in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "formats/crease_reconstruction.h"
#include "libbake/crease/crease_network.h"
#include "tests/crease/crease_test_maps.h"

namespace mbk {
namespace {

CurveSet random_polylines(uint32_t w, uint32_t h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(0.0, w), uy(0.0, h);
  CurveSet s;
  for (int c = 0; c < 12; ++c) {
    CurvePolyline line{{}, c % 3 == 0, "random"};
    for (int k = 0; k < 4; ++k) line.points.emplace_back(ux(rng), uy(rng));
    s.curves.push_back(line);
  }
  return s;
}

TEST(CreaseReconstruction, DistanceIsZeroOnEverySegment) {
  const uint32_t w = 40, h = 28;
  const BakedCrease baked = test::bake(test::flat_map(w, h), random_polylines(w, h, 3));
  const std::vector<CurveSegment> network = network_segments(baked.field);
  ASSERT_GT(network.size(), 100u);
  double worst = 0.0;
  for (const CurveSegment& s : network)
    for (int k = 0; k <= 16; ++k) {  // sub-texel points along the segment, its ends included
      const Vec2 p = s.a + (k / 16.0) * (s.b - s.a);
      worst = std::max(worst, reconstruct_crease(baked.field, p.x(), p.y()).distance);
    }
  // Zero up to the rounding of the sample point itself (a point computed on a segment is off it by ~1e-16).
  EXPECT_LE(worst, 1e-12);
}

TEST(CreaseReconstruction, DistanceMatchesTheMapAtSamples) {
  const BakedCrease baked = test::bake(test::flat_map(20, 20), random_polylines(20, 20, 4));
  const CreaseField& f = baked.field;
  for (uint32_t j = 1; j <= 20; ++j)
    for (uint32_t i = 1; i <= 20; ++i)
      EXPECT_NEAR(reconstruct_crease(f, i - 0.5, j - 0.5).distance, f.distance[f.sample_index(i, j)], 1e-12);
}

// On a map whose texels take normal (+a, 0, c) on one side of a line and (-a, 0, c) on the other, the normal
// reconstructed at 1,000 random points in every cell stays in its own side's hemisphere (sign of n_x), and the
// gradient points away from the line on the point's side.
void expect_sides_kept(const Vec2& a, const Vec2& b, uint32_t w, uint32_t h) {
  const NormalMap map = test::map_from(
      w, h, [&](const Vec2& p) { return Vec3(test::signed_line_distance(a, b, p) >= 0 ? 0.6 : -0.6, 0.0, 0.8); });
  CurveSet curves;
  curves.curves.push_back({{a, b}, false, "line"});
  const BakedCrease baked = test::bake(map, curves);
  const Vec2 away = Vec2(-(b - a).y(), (b - a).x()).normalized();  // towards side +1
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  uint64_t checked = 0, wrong_normal = 0, wrong_gradient = 0;
  // Cells whose four samples lie inside the map (the ring samples repeat border texels, whose side may differ).
  for (uint32_t j = 1; j < h; ++j)
    for (uint32_t i = 1; i < w; ++i)
      for (int k = 0; k < 1000; ++k) {
        const Vec2 p(i - 0.5 + u(rng), j - 0.5 + u(rng));
        const double sd = test::signed_line_distance(a, b, p);
        if (std::abs(sd) < 1e-5) continue;  // within float rounding of the stored crossings
        const CreaseSample s = reconstruct_crease(baked.field, p.x(), p.y());
        ++checked;
        wrong_normal += (s.normal[0] > 0) != (sd > 0);
        const double along = s.gradient[0] * away.x() + s.gradient[1] * away.y();
        wrong_gradient += s.distance < 3.0 && (along > 0) != (sd > 0);
      }
  EXPECT_GT(checked, uint64_t(990) * (w - 1) * (h - 1));
  EXPECT_EQ(wrong_normal, 0u);
  EXPECT_EQ(wrong_gradient, 0u);
}

TEST(CreaseReconstruction, OppositeSidesStayInTheirHemisphere) {
  expect_sides_kept({0.0, 2.37}, {19.0, 13.61}, 19, 16);
  expect_sides_kept({3.3, 16.0}, {11.9, 0.0}, 16, 16);   // steep, running up
  expect_sides_kept({0.0, 7.01}, {16.0, 7.93}, 16, 12);  // nearly along a lattice line
}

TEST(CreaseReconstruction, BilinearBaselineCrossesTheDiscontinuity) {
  // The same map through plain bilinear interpolation: points near the line on one side take the other
  // side's normal, which is what the reconstruction prevents.
  const Vec2 a(0.0, 2.37), b(19.0, 13.61);
  const NormalMap map = test::map_from(
      19, 16, [&](const Vec2& p) { return Vec3(test::signed_line_distance(a, b, p) >= 0 ? 0.6 : -0.6, 0.0, 0.8); });
  CurveSet curves;
  curves.curves.push_back({{a, b}, false, "line"});
  const BakedCrease baked = test::bake(map, curves);
  uint64_t wrong = 0;
  for (double x = 1.0; x < 18.0; x += 0.1) {
    const double y = a.y() + (x - a.x()) * (b - a).y() / (b - a).x() + 0.05;  // just below the line: side +1
    double n[3];
    bilinear_normal(baked.field, x, y, n);
    wrong += n[0] < 0;
  }
  EXPECT_GT(wrong, 20u);
}

TEST(CreaseReconstruction, ContinuousAcrossCellsAwayFromFeatures) {
  const uint32_t w = 32, h = 24;
  std::mt19937 rng(5);
  const NormalMap map = test::map_from(
      w, h, [](const Vec2& p) { return Vec3(0.4 * std::sin(p.x() * 0.7), 0.3 * std::cos(p.y() * 0.5), 1.0); });
  const BakedCrease baked = test::bake(map, random_polylines(w, h, 9));
  const CreaseField& f = baked.field;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double eps = 1e-9;
  double worst_distance = 0.0, worst_normal = 0.0, worst_gradient = 0.0;
  for (uint32_t j = 1; j < h; ++j)
    for (uint32_t i = 1; i < w; ++i)
      for (int k = 0; k < 50; ++k)
        for (int vertical = 0; vertical < 2; ++vertical) {
          // A point on the cell edge at x = i - 0.5 (vertical) or y = j - 0.5, evaluated from both cells.
          const double t = u(rng);
          const double x = vertical ? i - 0.5 : i - 0.5 + t, y = vertical ? j - 0.5 + t : j - 0.5;
          const CreaseSample lo = reconstruct_crease(f, x - (vertical ? eps : 0), y - (vertical ? 0 : eps));
          const CreaseSample hi = reconstruct_crease(f, x + (vertical ? eps : 0), y + (vertical ? 0 : eps));
          worst_distance = std::max(worst_distance, std::abs(lo.distance - hi.distance));
          const float crossing = vertical ? f.crossing_v[f.v_edge_index(i, j)] : f.crossing_h[f.h_edge_index(i, j)];
          if (crossing != kCreaseNoCrossing) continue;  // a feature on this edge: sides may differ along it
          for (int c = 0; c < 3; ++c) worst_normal = std::max(worst_normal, std::abs(lo.normal[c] - hi.normal[c]));
          for (int c = 0; c < 2; ++c)
            worst_gradient = std::max(worst_gradient, std::abs(lo.gradient[c] - hi.gradient[c]));
        }
  EXPECT_LT(worst_distance, 1e-7);  // continuous everywhere, features included
  EXPECT_LT(worst_normal, 1e-7);
  EXPECT_LT(worst_gradient, 1e-6);
}

// A sample that lies on a crease holds the normal of one side (or a mix): whichever it holds, the reconstruction
// must not carry it into the other side. Two planar facets split by the 45-degree line y = x + 1, which runs
// through the samples (i - 0.5, i + 0.5); the samples on it hold facet A's normal, facet B's, or their mean. Every
// point farther off the line than the crossings' nudge (2 kCreaseMinT) gets its own facet's normal exactly (without
// the on-curve rule: 0.84 off, the other facet's normal, where they hold B's; 0.43 where they hold the mean).
TEST(CreaseReconstruction, SamplesOnACreaseSpeakForNeitherSide) {
  const uint32_t w = 12, h = 12;
  const Vec2 a(0.0, 1.0), b(11.0, 12.0);
  const Vec3 facet_a = Vec3(0.6, 0.0, 0.8), facet_b = Vec3(0.0, -0.6, 0.8);
  const Vec3 on_curve_normals[] = {facet_a, facet_b, (facet_a + facet_b).normalized()};
  CurveSet curves;
  curves.curves.push_back({{a, b}, false, "diagonal through samples"});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(1.0, 11.0);
  for (const Vec3& on_curve : on_curve_normals) {
    const NormalMap map = test::map_from(w, h, [&](const Vec2& p) {
      const double side = test::signed_line_distance(a, b, p);
      return std::abs(side) < 1e-9 ? on_curve : side > 0 ? facet_a : facet_b;
    });
    const BakedCrease baked = test::bake(map, curves);
    double worst = 0.0;
    for (int k = 0; k < 20000; ++k) {
      const double x = u(rng), y = u(rng), side = test::signed_line_distance(a, b, Vec2(x, y));
      // On the line up to the crossings' nudge off the samples (kCreaseMinT), or near the curve's ends.
      if (std::abs(side) < 2 * kCreaseMinT || y < 1.5 || y > 11.5) continue;
      const Vec3 expected = side > 0 ? facet_a : facet_b;
      const CreaseSample s = reconstruct_crease(baked.field, x, y);
      const double e = (Vec3(s.normal[0], s.normal[1], s.normal[2]) - expected).norm();
      worst = std::max(worst, e);
    }
    EXPECT_LT(worst, 1e-6) << "on-curve samples hold (" << on_curve.transpose() << ")";
  }
}

// Three planar facets meeting at a point inside a cell (random junctions, three rays to the map's border, each
// leaving the junction's cell by its own edge: one crossing per edge is the lattice's limit): with the junction every
// point farther than 2 kCreaseMinT from the creases gets its own facet's normal exactly. Without junctions (at most
// two segments per cell, [Parilov05] Sec. 4.1) the junction's cell mixed two of the facets: 0.80 to 1.07 off.
TEST(CreaseReconstruction, JunctionCellsReproduceThreeFacetsExactly) {
  const uint32_t w = 16, h = 16;
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> cell(5, 10), quarter(0, 3);
  std::uniform_real_distribution<double> offset(-0.2, 0.2), jitter(-15.0, 15.0), u(1.0, 15.0);
  const Vec3 facet_normal[3] = {Vec3(0.5, 0.0, 0.8).normalized(), Vec3(-0.3, 0.4, 0.8).normalized(),
                                Vec3(0.0, -0.6, 0.8)};
  for (int trial = 0; trial < 40; ++trial) {
    const Vec2 j(cell(rng) + offset(rng), cell(rng) + offset(rng));  // within 0.2 of a cell's centre
    // Rays towards three different edges of the cell: right, down, left (y down), each within 15 degrees (which keeps
    // it on its edge from a point within 0.2 of the centre), turned by 90-degree steps.
    const double turn = 90.0 * quarter(rng), degrees = M_PI / 180.0;
    const double a[3] = {(turn + jitter(rng)) * degrees, (90.0 + turn + jitter(rng)) * degrees,
                         (180.0 + turn + jitter(rng)) * degrees};
    std::vector<Vec2> ends;
    for (double t : a) ends.push_back(j + 30.0 * Vec2(std::cos(t), std::sin(t)));
    const auto facet = [&](const Vec2& p) {  // the wedge between ray k and ray k + 1 (counter-clockwise in angle)
      const double t = std::atan2(p.y() - j.y(), p.x() - j.x());
      for (int k = 0; k < 3; ++k) {
        const double rel = std::remainder(t - a[k] - M_PI, 2.0 * M_PI) + M_PI;  // angle from ray k in [0, 2 pi)
        const double gap = std::remainder(a[(k + 1) % 3] - a[k] - M_PI, 2.0 * M_PI) + M_PI;
        if (rel < gap) return k;
      }
      return 0;
    };
    CurveSet curves;
    for (const Vec2& e : ends) curves.curves.push_back({{j, e}, false, "ray"});
    const BakedCrease baked =
        test::bake(test::map_from(w, h, [&](const Vec2& p) { return facet_normal[facet(p)]; }), curves);
    ASSERT_EQ(baked.field.junction_cells.size(), 1u) << trial;
    double worst = 0.0;
    for (int k = 0; k < 4000; ++k) {
      const Vec2 p(u(rng), u(rng));
      bool near_crease = false;
      for (const Vec2& e : ends)
        near_crease |= std::abs(test::signed_line_distance(j, e, p)) < 2 * kCreaseMinT && (p - j).dot(e - j) > 0.0;
      if (near_crease || (p - j).norm() < 2 * kCreaseMinT) continue;
      const CreaseSample s = reconstruct_crease(baked.field, p.x(), p.y());
      const double e = (Vec3(s.normal[0], s.normal[1], s.normal[2]) - facet_normal[facet(p)]).norm();
      worst = std::max(worst, e);
    }
    EXPECT_LT(worst, 1e-6) << "trial " << trial << ", junction (" << j.transpose() << ")";
  }
}

TEST(CreaseProfiles, EquationOneClosedForms) {
  CreaseSample s;
  s.distance = 0.0;
  s.gradient[0] = 0.6, s.gradient[1] = 0.8;  // texel coordinates: tangent space (0.6, -0.8)
  s.normal[0] = 0.0, s.normal[1] = 0.0, s.normal[2] = 1.0;
  CreaseProfile v;
  v.kind = CreaseProfileKind::v, v.depth = 2.0, v.width = 4.0, v.blend_start = 0.0, v.blend_end = 4.0;
  double n[3];
  // b(0) = 0: the profile's own normal (-p' g, 1) normalised, p' = depth / width = 0.5.
  crease_normal(s, v, n);
  const double len = std::sqrt(0.25 + 1.0);
  EXPECT_NEAR(n[0], -0.5 * 0.6 / len, 1e-12);
  EXPECT_NEAR(n[1], 0.5 * 0.8 / len, 1e-12);
  EXPECT_NEAR(n[2], 1.0 / len, 1e-12);
  // d >= w: b = 1, the map's normal.
  s.distance = 4.0;
  s.normal[0] = 0.28, s.normal[1] = -0.96, s.normal[2] = 0.0;
  crease_normal(s, v, n);
  EXPECT_NEAR(n[0], 0.28, 1e-12);
  EXPECT_NEAR(n[1], -0.96, 1e-12);
  // Half way: b = smoothstep(0.5) = 0.5, n' = (-(0.5) 0.5 g + 0.5 sqrt(1.25) B, 0.5 + 0.5 sqrt(1.25) B_z).
  s.distance = 2.0;
  s.normal[0] = 0.0, s.normal[1] = 0.6, s.normal[2] = 0.8;
  crease_normal(s, v, n);
  const double bt = 0.5 * std::sqrt(1.25);
  const double ex = -0.25 * 0.6, ey = 0.25 * 0.8 + bt * 0.6, ez = 0.5 + bt * 0.8,
               el = std::sqrt(ex * ex + ey * ey + ez * ez);
  EXPECT_NEAR(n[0], ex / el, 1e-12);
  EXPECT_NEAR(n[1], ey / el, 1e-12);
  EXPECT_NEAR(n[2], ez / el, 1e-12);
}

TEST(CreaseProfiles, SlopesOfEachKind) {
  CreaseProfile p;
  p.depth = 2.0, p.width = 4.0;
  p.kind = CreaseProfileKind::v;
  EXPECT_EQ(p.slope(1.0, 1), 0.5);
  EXPECT_EQ(p.slope(4.0, 1), 0.0);  // flat beyond the width
  p.kind = CreaseProfileKind::rounded;
  EXPECT_EQ(p.slope(0.0, 1), 0.0);  // rounded bottom
  EXPECT_NEAR(p.slope(2.0, 1), 2.0 * 2.0 * 2.0 / 16.0, 1e-15);
  p.kind = CreaseProfileKind::step;
  EXPECT_EQ(p.slope(1.0, 1), 0.5);
  EXPECT_EQ(p.slope(1.0, -1), 0.0);  // one-sided
  p.kind = CreaseProfileKind::table;
  p.table = {0.0, 1.0, 1.5};  // samples at d = 0, 2, 4
  EXPECT_EQ(p.slope(1.0, 1), 0.5);
  EXPECT_EQ(p.slope(3.0, 1), 0.25);
  // Finite differences of the table interpolant.
  const double h = 1e-6;
  EXPECT_NEAR(p.slope(2.7, 1),
              ((0.0 + 1.0 + (2.7 + h - 2.0) / 2.0 * 0.5) - (1.0 + (2.7 - h - 2.0) / 2.0 * 0.5)) / (2 * h), 1e-6);
}

TEST(CreaseProfiles, BlendIsZeroInsideW0AndOneBeyondW) {
  CreaseProfile p;
  p.blend_start = 0.5, p.blend_end = 2.0;
  EXPECT_EQ(crease_blend(p, 0.0), 0.0);
  EXPECT_EQ(crease_blend(p, 0.5), 0.0);
  EXPECT_EQ(crease_blend(p, 2.0), 1.0);
  EXPECT_NEAR(crease_blend(p, 1.25), 0.5, 1e-15);
  p.blend_start = p.blend_end = 0.0;  // no band: the map everywhere
  EXPECT_EQ(crease_blend(p, 0.0), 1.0);
}

}  // namespace
}  // namespace mbk
