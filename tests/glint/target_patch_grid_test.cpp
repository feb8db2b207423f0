// The point query's target grid (libbake/glint/target_patch_grid.h, [Wang20] Sec. 4.2): the hash is pinned to
// fixed values (computed independently of this code, from the PCG definition), every patch lies inside the
// example for any vertex including negative and extreme indices, the weights are the bilinear tent functions of
// the grid vertices (so they sum to 1) with exact gradients, and the four corners read their patches
// consistently (the same vertex maps the same u to the same example point from every target patch).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "formats/error.h"
#include "libbake/core/hash.h"
#include "libbake/glint/target_patch_grid.h"

namespace mbk {
namespace {

double tent(double t) { return std::max(0.0, 1.0 - std::abs(t)); }

TEST(TargetPatchGrid, HashAndOriginsArePinnedToPlatformIndependentValues) {
  // Values from a separate Python transcription of libbake/core/hash.h (32-bit unsigned arithmetic).
  EXPECT_EQ(pcg_hash(0u), 129708002u);
  EXPECT_EQ(pcg_hash(1u), 2831084092u);
  EXPECT_EQ(pcg_hash(123456789u), 4272394698u);
  const TargetPatchGrid grid(128, 96, 32, 7);
  using O = std::array<uint32_t, 2>;
  EXPECT_EQ(grid.patch_origin(0, 0), (O{10, 18}));
  EXPECT_EQ(grid.patch_origin(-1, 0), (O{52, 56}));
  EXPECT_EQ(grid.patch_origin(5, -7), (O{62, 48}));
  EXPECT_EQ(grid.patch_origin(-2147483648LL, 2147483647LL), (O{75, 59}));
}

TEST(TargetPatchGrid, PatchesLieInsideTheExampleForAnyVertex) {
  std::mt19937_64 rng(11);
  for (const auto& [w, h, p] : {std::array<uint32_t, 3>{128, 128, 32}, {37, 50, 37}, {2, 2, 2}, {300, 7, 6}}) {
    const TargetPatchGrid grid(w, h, p, 3);
    std::uniform_int_distribution<int64_t> small(-1000, 1000);
    std::uniform_int_distribution<int64_t> any(std::numeric_limits<int64_t>::min(),
                                               std::numeric_limits<int64_t>::max());
    for (int n = 0; n < 20000; ++n) {
      const bool far = n % 2 == 1;
      const int64_t a = far ? any(rng) : small(rng), b = far ? any(rng) : small(rng);
      const auto o = grid.patch_origin(a, b);
      ASSERT_LE(o[0] + p, w) << a << "," << b;
      ASSERT_LE(o[1] + p, h) << a << "," << b;
    }
    // Every origin is reachable: both extremes occur among the small vertices.
    uint32_t lo = w, hi = 0;
    for (int64_t a = -200; a < 200; ++a)
      for (int64_t b = -5; b < 5; ++b) {
        lo = std::min(lo, grid.patch_origin(a, b)[0]);
        hi = std::max(hi, grid.patch_origin(a, b)[0]);
      }
    EXPECT_EQ(lo, 0u);
    EXPECT_EQ(hi, w - p);
  }
}

TEST(TargetPatchGrid, WeightsAreTheVertexTentsSumToOneWithExactGradients) {
  const TargetPatchGrid grid(128, 128, 32, 5);
  const double h = grid.target_side();
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> pos(-2000.0, 2000.0);
  for (int n = 0; n < 10000; ++n) {
    const Vec2 u(pos(rng), pos(rng));
    const TargetPatchLocation loc = grid.locate(u);
    double sum = 0.0;
    for (const TargetPatchCorner& c : loc.corners) {
      sum += c.weight;
      // Bilinear: the product of the 1-D tents centred on the vertex, of half-width h.
      EXPECT_NEAR(c.weight, tent(u.x() / h - double(c.a)) * tent(u.y() / h - double(c.b)), 1e-12);
      // Gradient: d/du of the tent product, on the patch's own (smooth) piece.
      const double tx = tent(u.x() / h - double(c.a)), ty = tent(u.y() / h - double(c.b));
      const double sx = double(c.a) > u.x() / h ? 1.0 : -1.0, sy = double(c.b) > u.y() / h ? 1.0 : -1.0;
      EXPECT_NEAR(c.weight_gradient.x(), sx * ty / h, 1e-12);
      EXPECT_NEAR(c.weight_gradient.y(), tx * sy / h, 1e-12);
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
  }
}

TEST(TargetPatchGrid, EachVertexReadsItsPatchAtTheSameExamplePointFromEveryTargetPatch) {
  const TargetPatchGrid grid(100, 90, 20, 9);
  const double h = grid.target_side();
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> pos(-500.0, 500.0);
  for (int n = 0; n < 5000; ++n) {
    const Vec2 u(pos(rng), pos(rng));
    for (const TargetPatchCorner& c : grid.locate(u).corners) {
      const auto o = grid.patch_origin(c.a, c.b);
      const Vec2 expected = Vec2(o[0], o[1]) + u - Vec2(double(c.a - 1) * h, double(c.b - 1) * h);
      EXPECT_NEAR((c.example_point - expected).norm(), 0.0, 1e-9);
      EXPECT_GE(c.example_point.x(), o[0]);
      EXPECT_LE(c.example_point.x(), o[0] + 20.0);
      EXPECT_GE(c.example_point.y(), o[1]);
      EXPECT_LE(c.example_point.y(), o[1] + 20.0);
    }
  }
}

TEST(TargetPatchGrid, RejectsBadPatchSidesAndPositions) {
  EXPECT_THROW(TargetPatchGrid(64, 64, 1, 0), Error);
  EXPECT_THROW(TargetPatchGrid(64, 32, 33, 0), Error);
  const TargetPatchGrid grid(64, 64, 16, 0);
  EXPECT_THROW(grid.locate(Vec2(std::nan(""), 0.0)), Error);
  EXPECT_THROW(grid.locate(Vec2(0.0, 1e300)), Error);
  EXPECT_NO_THROW(grid.locate(Vec2(-1e12, 1e12)));
}

}  // namespace
}  // namespace mbk
