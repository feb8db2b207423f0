// Distance, gradient and side maps ([Parilov05] Sec. 4.2; libbake/crease/crease_distance.h) against brute force
// over every network segment, and the constrained gradient smoothing (gradient_smoothing.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "libbake/core/parallel.h"
#include "libbake/crease/crease_distance.h"
#include "libbake/crease/crease_network.h"
#include "libbake/crease/gradient_smoothing.h"
#include "tests/crease/crease_test_maps.h"

namespace mbk {
namespace {

std::vector<CurveSegment> random_segments(uint32_t w, uint32_t h, size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(0.0, w), uy(0.0, h);
  std::vector<CurveSegment> out;
  for (size_t k = 0; k < n; ++k) out.push_back({{ux(rng), uy(rng)}, {ux(rng), uy(rng)}});
  return out;
}

TEST(CreaseDistance, ExactWithinBandUpperBoundBeyond) {
  const uint32_t w = 61, h = 45;
  CreaseField f;
  f.allocate(w, h);
  simplify_curves(test::curves_of(random_segments(w, h, 6, 7)), f);
  const std::vector<CurveSegment> network = network_segments(f);
  ASSERT_FALSE(network.empty());
  const double band = 3.0;
  compute_distance_maps(network, band, f, Progress::silent());
  double worst_beyond = 0.0;
  for (uint32_t j = 0; j < f.samples_y(); ++j)
    for (uint32_t i = 0; i < f.samples_x(); ++i) {
      const Vec2 p(i - 0.5, j - 0.5);
      double exact = 1e300;
      for (const CurveSegment& s : network) exact = std::min(exact, segment_distance(s, p));
      const double stored = f.distance[f.sample_index(i, j)];
      if (exact <= band)
        EXPECT_NEAR(stored, exact, 1e-6 * (1 + exact)) << i << "," << j;  // float storage
      else
        EXPECT_GE(stored, exact - 1e-5) << i << "," << j;
      worst_beyond = std::max(worst_beyond, stored - exact);
    }
  RecordProperty("worst_propagation_error", std::to_string(worst_beyond));
  EXPECT_LT(worst_beyond, 0.5);  // the propagated candidate is never far from the nearest
}

TEST(CreaseDistance, InsideTheBandEverySampleKeepsTheSmallestIndexOfItsNearestWhateverTheThreadCount) {
  // A dense network at a realistic size (its segments share end points, so ties between neighbours are common):
  // inside the band the side map is that of the nearest segment with the smallest index (brute force over every
  // segment), which the propagation beyond the band must never change; 1 and 2 threads store the same maps.
  const uint32_t w = 160, h = 120;
  const double band = 2.5;
  CreaseField one, two;
  one.allocate(w, h);
  simplify_curves(test::curves_of(random_segments(w, h, 120, 11)), one);
  two = one;
  const std::vector<CurveSegment> network = network_segments(one);
  set_thread_count(1);
  compute_distance_maps(network, band, one, Progress::silent());
  set_thread_count(2);
  compute_distance_maps(network, band, two, Progress::silent());
  set_thread_count(0);
  EXPECT_EQ(one.distance, two.distance);
  EXPECT_EQ(one.gradient, two.gradient);
  EXPECT_EQ(one.side, two.side);
  size_t checked = 0;
  for (uint32_t j = 0; j < one.samples_y(); ++j)
    for (uint32_t i = 0; i < one.samples_x(); ++i) {
      const Vec2 p(i - 0.5, j - 0.5);
      double nearest = std::numeric_limits<double>::infinity();
      size_t s = 0;
      for (size_t k = 0; k < network.size(); ++k)
        if (const double d = segment_distance(network[k], p); d < nearest) nearest = d, s = k;
      if (nearest > band || nearest < 1e-9) continue;
      const Vec2 dir = network[s].b - network[s].a, q = p - network[s].a;
      EXPECT_EQ(one.side[one.sample_index(i, j)], dir.x() * q.y() - dir.y() * q.x() >= 0.0 ? 1 : -1) << i << "," << j;
      ++checked;
    }
  EXPECT_GT(checked, size_t(w * h / 2));
}

TEST(CreaseDistance, GradientPointsAwayFromNearestPointAndSideFollowsDirection) {
  CreaseField f;
  f.allocate(16, 16);
  const CurveSegment line{{0.0, 3.3}, {16.0, 12.1}};  // directed right and down
  simplify_curves(test::curves_of({line}), f);
  compute_distance_maps(network_segments(f), 4.0, f, Progress::silent());
  for (uint32_t j = 3; j < 14; ++j)  // away from the ends, where the nearest point is an end point
    for (uint32_t i = 3; i < 14; ++i) {
      const Vec2 p(i - 0.5, j - 0.5);
      const double sd = test::signed_line_distance(line.a, line.b, p);
      if (std::abs(sd) < 0.01 || std::abs(sd) > 3.0) continue;
      const size_t k = f.sample_index(i, j);
      EXPECT_EQ(f.side[k], sd > 0 ? 1 : -1) << i << "," << j;
      // Away from the line: the line's normal times the side.
      const Vec2 normal = Vec2(-(line.b - line.a).y(), (line.b - line.a).x()).normalized() * (sd > 0 ? 1.0 : -1.0);
      EXPECT_NEAR(f.gradient[2 * k], normal.x(), 1e-3) << i << "," << j;
      EXPECT_NEAR(f.gradient[2 * k + 1], normal.y(), 1e-3) << i << "," << j;
    }
}

TEST(GradientSmoothing, NeverAveragesAcrossACrossing) {
  // A vertical curve at x = 4.2 splits the lattice; every sample's gradient starts at its side's value.
  CreaseField f;
  f.allocate(10, 6);
  simplify_curves(test::curves_of({{{4.2, 0.0}, {4.2, 6.0}}}), f);
  for (uint32_t j = 0; j < f.samples_y(); ++j)
    for (uint32_t i = 0; i < f.samples_x(); ++i) {
      const size_t k = f.sample_index(i, j);
      const bool left = i - 0.5 < 4.2;
      f.gradient[2 * k] = left ? -1.0f : 1.0f;
      f.gradient[2 * k + 1] = 0.0f;
    }
  smooth_gradient(f, 50);
  for (uint32_t j = 0; j < f.samples_y(); ++j)
    for (uint32_t i = 0; i < f.samples_x(); ++i) {
      const size_t k = f.sample_index(i, j);
      EXPECT_EQ(f.gradient[2 * k], i - 0.5 < 4.2 ? -1.0f : 1.0f) << i << "," << j;
    }
}

TEST(GradientSmoothing, SmoothsTheMedialAxisAndKeepsUnitLength) {
  // Inside an L-shaped crease the gradient jumps by 90 degrees across the bisector (the medial axis meeting
  // the corner, Fig. 6); smoothing turns it gradually, never changes the distance, keeps unit length.
  const uint32_t n = 24;
  CurveSet curves;
  curves.curves.push_back({{{4.2, 24.0}, {4.2, 4.2}, {24.0, 4.2}}, false, "L"});
  const BakedCrease raw = test::bake(test::flat_map(n, n), curves, 0, 30.0);
  const BakedCrease smooth = test::bake(test::flat_map(n, n), curves, 10, 30.0);
  auto largest_jump = [&](const CreaseField& f) {
    double worst = 0;
    for (uint32_t j = 9; j < 20; ++j)
      for (uint32_t i = 9; i < 20; ++i) {
        const size_t a = f.sample_index(i, j), b = f.sample_index(i + 1, j);
        worst = std::max(worst, std::hypot(double(f.gradient[2 * a]) - f.gradient[2 * b],
                                           double(f.gradient[2 * a + 1]) - f.gradient[2 * b + 1]));
      }
    return worst;
  };
  EXPECT_NEAR(largest_jump(raw.field), std::sqrt(2.0), 1e-6);
  EXPECT_LT(largest_jump(smooth.field), 0.5);
  for (size_t k = 0; k < smooth.field.distance.size(); ++k)
    EXPECT_NEAR(std::hypot(smooth.field.gradient[2 * k], smooth.field.gradient[2 * k + 1]), 1.0, 1e-6);
  EXPECT_EQ(raw.field.distance, smooth.field.distance);  // the distance itself is never smoothed
}

}  // namespace
}  // namespace mbk
