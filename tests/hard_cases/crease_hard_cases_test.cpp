// Hard cases of creases ([Parilov05]; libbake/crease/, formats/crease_reconstruction.h) where the curves meet the
// lattice of texel centres badly: a crease through texel centres, crease ends inside a texel, two creases closer
// than a texel, a closed curve. Maps take one normal per side of the curves, so the exact answer is known
// everywhere: the reconstructed normal must be its side's normal (never a blend across the crease), and the
// reconstructed distance the exact distance to the (simplified) curve, which barycentric interpolation of the
// lattice's exact distances reproduces for straight pieces.
// (A 1 x 1 map, curves along lattice lines, normals at the horizon on both sides: CreaseBake.*.)
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "formats/crease_reconstruction.h"
#include "tests/crease/crease_test_maps.h"

namespace mbk {
namespace {

const Vec3 kPositive = Vec3(0.6, 0.0, 0.8), kNegative = Vec3(-0.48, 0.36, 0.8);

// Crossings are kept 1/1024 of a texel off the lattice samples (formats/crease_field.h: kCreaseMinT), so the
// network may sit that far from the input curve.
constexpr double kCrossingClamp = 1.0 / 1024;

struct Expectation {
  std::function<double(const Vec2&)> side;      // > 0: kPositive's side
  std::function<double(const Vec2&)> distance;  // the exact distance to the network, or < 0 where not asserted
};

// 2,000 random points per cell whose four samples are inside the map (the ring samples repeat border texels).
// Returns the number of points whose side was checked; stops at the first failure.
uint64_t expect_sides_and_distances(const BakedCrease& baked, uint32_t w, uint32_t h, const Expectation& e,
                                    double side_margin, double distance_tolerance) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  uint64_t checked = 0;
  for (uint32_t j = 1; j < h; ++j)
    for (uint32_t i = 1; i < w; ++i)
      for (int k = 0; k < 2000; ++k) {
        const Vec2 p(i - 0.5 + u(rng), j - 0.5 + u(rng));
        const CreaseSample s = reconstruct_crease(baked.field, p.x(), p.y());
        const Vec3 n(s.normal[0], s.normal[1], s.normal[2]);
        const double side = e.side(p);
        if (std::abs(side) > side_margin) {
          ++checked;
          if ((n - (side > 0 ? kPositive : kNegative)).norm() > 1e-6) {
            ADD_FAILURE() << "normal (" << n.transpose() << ") on the wrong side at (" << p.transpose() << ")";
            return checked;
          }
        }
        const double d = e.distance(p);
        if (d >= 0.0 && std::abs(s.distance - d) > distance_tolerance) {
          ADD_FAILURE() << "distance " << s.distance << " instead of " << d << " at (" << p.transpose() << ")";
          return checked;
        }
      }
  return checked;
}

double line_distance(const Vec2& a, const Vec2& b, const Vec2& p) { return test::signed_line_distance(a, b, p); }

// Protects against: a crease through lattice samples (texel centres), where a crossing falls on a cell corner and
// an edge point would coincide with it (degenerate triangles, 0/0 in barycentric weights). A sample on the curve
// belongs to the side left of (above) the curve, as the network's perturbation of the curve by (+eps, +eps^2)
// puts it (crease_network.h); the map gives it that side's normal.
TEST(HardCases, CreaseThroughTexelCentres) {
  for (const auto& [a, b] : {std::pair{Vec2(3.5, 0.0), Vec2(3.5, 9.0)}, {Vec2(0.0, 0.0), Vec2(9.0, 9.0)}}) {
    // line_distance(b, a, p) > 0 right of (above) the curve; 0 on it.
    const NormalMap map =
        test::map_from(10, 9, [&](const Vec2& p) { return line_distance(b, a, p) > 0 ? kPositive : kNegative; });
    const BakedCrease baked = test::bake(map, test::curves_of({{a, b}}));
    const Expectation e{[&](const Vec2& p) { return line_distance(b, a, p); },
                        [&](const Vec2& p) {
                          const double along = (p - a).dot((b - a).normalized());
                          // Two texels from the ends, where the nearest network point is an end point.
                          return along > 2.0 && along < (b - a).norm() - 2.0 ? std::abs(line_distance(a, b, p)) : -1.0;
                        }};
    EXPECT_GT(expect_sides_and_distances(baked, 10, 9, e, 2 * kCrossingClamp, 2 * kCrossingClamp), 100000u);
  }
}

// Protects against: curve ends inside a texel (the part inside the end cells is dropped, [Parilov05] Sec. 4.1):
// in the cells the crease crosses whole, sides and distances must be exact; everywhere, the network lies on the
// input segment, so the reconstructed distance is never below the distance to it; past the ends the map is
// continuous and the reconstruction must be finite with unit normals.
TEST(HardCases, CreaseEndpointsInsideATexel) {
  const Vec2 a(2.3, 4.2), b(9.6, 4.7);
  const double length = (b - a).norm();
  const auto along = [&](const Vec2& p) { return (p - a).dot((b - a) / length); };
  const auto segment_distance = [&](const Vec2& p) {
    const double t = std::clamp(along(p), 0.0, length);
    return (p - (a + t * (b - a) / length)).norm();
  };
  // Beyond the ends both sides have the same normal; between them, one per side.
  const NormalMap map = test::map_from(12, 9, [&](const Vec2& p) {
    const bool between = along(p) > 0 && along(p) < length;
    return between && line_distance(a, b, p) >= 0 ? kPositive : kNegative;
  });
  const BakedCrease baked = test::bake(map, test::curves_of({{a, b}}));
  const Expectation e{
      [&](const Vec2& p) { return along(p) > 3.0 && along(p) < length - 3.0 ? line_distance(a, b, p) : 0.0; },
      [&](const Vec2& p) {
        return along(p) > 3.0 && along(p) < length - 3.0 ? std::abs(line_distance(a, b, p)) : -1.0;
      }};
  EXPECT_GT(expect_sides_and_distances(baked, 12, 9, e, 2 * kCrossingClamp, 2 * kCrossingClamp), 10000u);
  for (double y = 0.0; y <= 9.0; y += 0.05)
    for (double x = 0.0; x <= 12.0; x += 0.05) {
      const CreaseSample s = reconstruct_crease(baked.field, x, y);
      ASSERT_GE(s.distance, segment_distance(Vec2(x, y)) - 2 * kCrossingClamp) << x << "," << y;
      ASSERT_NEAR(std::sqrt(s.normal[0] * s.normal[0] + s.normal[1] * s.normal[1] + s.normal[2] * s.normal[2]), 1.0,
                  1e-12);
    }
}

// Protects against: two creases closer than a texel (0.4 apart, no sample between them), which cross each vertical
// cell edge twice: the crossings merge at their centre of mass into one crease on the mean line, and the strip
// between the creases (which no sample holds) must never make interpolation blend the outer two normals.
TEST(HardCases, CreaseTwoCreasesCloserThanATexel) {
  const Vec2 a1(0.0, 4.55), b1(12.0, 4.65), a2(0.0, 4.95), b2(12.0, 5.05);
  // The merged crease: the mean line, from its crossing of the first lattice line (x = 0.5) to the last (x = 11.5);
  // the pieces in the end cells are dropped.
  const Vec2 am = 0.5 * (a1 + a2) + (0.5 / 12) * (b1 + b2 - a1 - a2) / 2,
             bm = 0.5 * (a1 + a2) + (11.5 / 12) * (b1 + b2 - a1 - a2) / 2;
  const auto network_distance = [&](const Vec2& p) {
    const double t = std::clamp((p - am).dot(bm - am) / (bm - am).squaredNorm(), 0.0, 1.0);
    return (p - (am + t * (bm - am))).norm();
  };
  const NormalMap map = test::map_from(12, 9, [&](const Vec2& p) {
    if (line_distance(a1, b1, p) < 0) return kNegative;   // above the first crease
    if (line_distance(a2, b2, p) >= 0) return kPositive;  // below the second
    return Vec3(0.0, -0.6, 0.8);                          // between: held by no sample
  });
  const BakedCrease baked = test::bake(map, test::curves_of({{a1, b1}, {a2, b2}}));
  EXPECT_GT(baked.simplify.merged_edges, 0u);
  const Expectation e{[&](const Vec2& p) { return line_distance(am, bm, p); },
                      [&](const Vec2& p) {
                        // Exact within the band (4 texels; an upper bound beyond) and away from the network's
                        // ends (where the distance to an end point is not linear over a cell).
                        const double d = network_distance(p);
                        return d < 3.0 && p.x() > 1.5 && p.x() < 10.5 ? d : -1.0;
                      }};
  EXPECT_GT(expect_sides_and_distances(baked, 12, 9, e, 1e-3, 1e-5), 100000u);
}

// Protects against: a closed curve, whose last piece must join its first (a gap where the loop closes would let
// the inside normal leak out), with the loop's start inside a cell. A 64-gon of radius 4.3: inside one normal,
// outside the other. Margins: the network replaces the arc in each cell by a chord (at most the cell's diagonal,
// sagitta <= 2 / (8 R) texel),
// and within one texel of it the distance |r - R| is curved (second derivative 1 / r), which linear interpolation
// over a cell misses by up to 1 / (8 (R - 1)).
TEST(HardCases, CreaseClosedCurve) {
  const Vec2 centre(8.2, 7.9);
  const double R = 4.3;
  CurvePolyline loop{{}, true, "circle"};
  for (int k = 0; k < 64; ++k) {
    const double t = 2 * std::numbers::pi * (k + 0.3) / 64;
    loop.points.push_back(centre + R * Vec2(std::cos(t), std::sin(t)));
  }
  CurveSet curves;
  curves.curves.push_back(loop);
  const NormalMap map =
      test::map_from(16, 16, [&](const Vec2& p) { return (p - centre).norm() < R ? kPositive : kNegative; });
  const BakedCrease baked = test::bake(map, curves);
  const double margin = 2.0 / (8 * R) + 0.01, distance_tolerance = margin + 1.0 / (8 * (R - 1));
  const Expectation e{[&](const Vec2& p) { return R - (p - centre).norm(); },
                      [&](const Vec2& p) {
                        const double d = std::abs((p - centre).norm() - R);
                        return d < 1.0 ? d : -1.0;
                      }};
  EXPECT_GT(expect_sides_and_distances(baked, 16, 16, e, margin, distance_tolerance), 300000u);
}

}  // namespace
}  // namespace mbk
