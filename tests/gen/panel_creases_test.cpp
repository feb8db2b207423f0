// The panels' crease segments are exactly where the normal map's slope jumps: away from every segment the
// normals are locally constant (the height is linear over each central-difference stencil), and across the
// middle of every segment they change. Raised panels face outward on their bevels in +Y (top bevel up).
#include <gtest/gtest.h>

#include <cmath>

#include "libbake/gen/panels.h"

namespace mbk {
namespace {

double distance_to_segment(const Vec2& p, const CreaseSegment& s) {
  const Vec2 d = s.b - s.a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - s.a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - s.a - t * d).norm();
}

// Distance from p to the nearest crease, over the periodic copies of the map.
double distance_to_creases(const Vec2& p, const std::vector<CreaseSegment>& creases, const MapSize& size) {
  double best = INFINITY;
  for (int oy = -1; oy <= 1; ++oy)
    for (int ox = -1; ox <= 1; ++ox)
      for (const CreaseSegment& s : creases)
        best = std::min(best, distance_to_segment(p + Vec2(ox * double(size.width), oy * double(size.height)), s));
  return best;
}

class PanelSizes : public ::testing::TestWithParam<MapSize> {};

TEST_P(PanelSizes, NormalsAreConstantAwayFromCreases) {
  const MapSize size = GetParam();
  const NormalMap m = generate_panels(size, 8, Progress::silent());
  const auto creases = panel_creases(size, 8);
  ASSERT_FALSE(creases.empty());
  size_t checked = 0;
  for (uint32_t r = 0; r < size.height; ++r)
    for (uint32_t x = 0; x < size.width; ++x) {
      // The stencils of (x, r) and its 4 neighbours reach 2 texels (in x or y): beyond 2.05 texels from every
      // crease, all five see one linear piece of the height.
      if (distance_to_creases(Vec2(x + 0.5, r + 0.5), creases, size) < 2.05) continue;
      const uint32_t xr = (x + 1) % size.width, down = (r + 1) % size.height;
      EXPECT_LT((m.at(x, r) - m.at(xr, r)).norm(), 1e-6f) << "(" << x << ", " << r << ")";
      EXPECT_LT((m.at(x, r) - m.at(x, down)).norm(), 1e-6f) << "(" << x << ", " << r << ")";
      ++checked;
    }
  EXPECT_GT(checked, size_t(size.width) * size.height / 3);
}

TEST_P(PanelSizes, ExactNormalIsTheMapAwayFromCreases) {
  // panel_normal is the surface the map samples: where the central-difference stencil sees one linear piece
  // (beyond 1.05 texels from every crease), the map's texel is the exact normal at its centre.
  const MapSize size = GetParam();
  const NormalMap m = generate_panels(size, 8, Progress::silent());
  const PanelLayout layout = panel_layout(size, 8);
  const auto creases = panel_creases(layout);
  size_t checked = 0, sloped = 0;
  for (uint32_t r = 0; r < size.height; ++r)
    for (uint32_t x = 0; x < size.width; ++x) {
      const Vec2 p(x + 0.5, r + 0.5);
      if (distance_to_creases(p, creases, size) < 1.05) continue;
      const Vec3 exact = panel_normal(layout, p);
      EXPECT_LT((m.at(x, r).cast<double>() - exact).norm(), 1e-6) << "(" << x << ", " << r << ")";
      sloped += exact.z() < 0.99;
      ++checked;
    }
  EXPECT_GT(checked, size_t(size.width) * size.height / 3);
  EXPECT_GT(sloped, checked / 20);  // bevels are checked too, not only flat tops
}

TEST_P(PanelSizes, NormalsChangeAcrossEveryCrease) {
  const MapSize size = GetParam();
  const NormalMap m = generate_panels(size, 8, Progress::silent());
  size_t tested = 0;
  for (const CreaseSegment& s : panel_creases(size, 8)) {
    const Vec2 d = s.b - s.a;
    if (d.norm() < 6.0) continue;  // too short to have texels on both sides clear of its ends
    const Vec2 mid = 0.5 * (s.a + s.b), across = Vec2(-d.y(), d.x()).normalized();
    auto normal_at = [&](const Vec2& p) {
      const int64_t x = int64_t(std::floor(p.x())), r = int64_t(std::floor(p.y()));
      return m.at(uint32_t((x % size.width + size.width) % size.width),
                  uint32_t((r % size.height + size.height) % size.height));
    };
    const Vec3f a = normal_at(mid + 1.6 * across), b = normal_at(mid - 1.6 * across);
    EXPECT_GT((a - b).norm(), 0.2f) << "segment (" << s.a.transpose() << ") - (" << s.b.transpose() << ")";
    ++tested;
  }
  EXPECT_GT(tested, 20u);
}

INSTANTIATE_TEST_SUITE_P(Sizes, PanelSizes, ::testing::Values(MapSize{256, 256}, MapSize{300, 170}, MapSize{97, 211}));

TEST(Panels, RaisedBevelsFaceOutwardInPlusY) {
  const MapSize size{256, 256};
  const PanelLayout layout = panel_layout(size, 8);
  const NormalMap m = generate_panels(size, 8, Progress::silent());
  const BevelledRect& r = layout.rects.front();
  ASSERT_EQ(r.rise, 1.0);
  const uint32_t mid_x = uint32_t(0.5 * (r.lo.x() + r.hi.x())), mid_row = uint32_t(0.5 * (r.lo.y() + r.hi.y()));
  const uint32_t top_row = uint32_t(r.lo.y() + 0.5 * r.bevel), left_x = uint32_t(r.lo.x() + 0.5 * r.bevel);
  EXPECT_NEAR(m.at(mid_x, top_row).y(), std::sqrt(0.5f), 1e-6f);    // the top bevel faces up (+v): green high
  EXPECT_NEAR(m.at(left_x, mid_row).x(), -std::sqrt(0.5f), 1e-6f);  // the left bevel faces left: red low
}

TEST(Panels, TinyMapsStayValid) {
  for (MapSize size : {MapSize{1, 1}, MapSize{4, 4}, MapSize{9, 2}, MapSize{16, 16}}) {
    const auto creases = panel_creases(size, 1);
    for (const CreaseSegment& s : creases)
      for (const Vec2& p : {s.a, s.b}) {
        EXPECT_GE(p.x(), 0.0);
        EXPECT_LE(p.x(), double(size.width));
        EXPECT_GE(p.y(), 0.0);
        EXPECT_LE(p.y(), double(size.height));
      }
  }
}

}  // namespace
}  // namespace mbk
