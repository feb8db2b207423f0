// The reconstruction on every allowed cell configuration (formats/crease_reconstruction.h), not only those the
// simplifier happens to produce: random fields with random crossings (or none) on every edge and, per cell, a
// random allowed word (no segment, one, or two of the six, including the X of both diagonals, two corner cuts,
// and two segments sharing an end point: the appendix's case 3.1.3). Everything stays finite and unit length,
// the distance is continuous across every cell edge and 0 at every crossing, and at points near a segment on
// either side the reconstruction takes values only from its own side's corners.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

#include "formats/crease_reconstruction.h"

namespace mbk {
namespace {

CreaseField random_field(uint32_t w, uint32_t h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CreaseField f;
  f.allocate(w, h);
  for (size_t k = 0; k < f.normals.size() / 3; ++k) {
    const double x = u(rng) - 0.5, y = u(rng) - 0.5, z = 1.0, len = std::sqrt(x * x + y * y + z * z);
    f.normals[3 * k] = float(x / len), f.normals[3 * k + 1] = float(y / len), f.normals[3 * k + 2] = float(z / len);
  }
  for (size_t k = 0; k < f.distance.size(); ++k) {
    f.distance[k] = float(3.0 * u(rng));
    const double a = 2 * M_PI * u(rng);
    f.gradient[2 * k] = float(std::cos(a)), f.gradient[2 * k + 1] = float(std::sin(a));
    f.side[k] = u(rng) < 0.5 ? 1 : -1;
  }
  for (float& t : f.crossing_h)
    t = u(rng) < 0.6 ? float(kCreaseMinT + (1 - 2 * kCreaseMinT) * u(rng)) : kCreaseNoCrossing;
  for (float& t : f.crossing_v)
    t = u(rng) < 0.6 ? float(kCreaseMinT + (1 - 2 * kCreaseMinT) * u(rng)) : kCreaseNoCrossing;
  for (uint32_t j = 0; j < f.cells_y(); ++j)
    for (uint32_t i = 0; i < f.cells_x(); ++i) {
      const CreaseCellEdges c = crease_cell_edges(f, i, j);
      std::vector<int> allowed;
      for (int bit = 0; bit < 6; ++bit)
        if (c.crossing[kCreasePairFirst[bit]] && c.crossing[kCreasePairSecond[bit]]) allowed.push_back(bit);
      uint16_t mask = 0;
      const int want = int(rng() % 3);
      for (int n = 0; n < want && !allowed.empty(); ++n) mask |= uint16_t(1u << allowed[rng() % allowed.size()]);
      f.segments[f.cell_index(i, j)] = mask;
    }
  return f;
}

TEST(CreaseConfigurations, EveryAllowedConfigurationIsFiniteAndContinuous) {
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    const uint32_t w = 12, h = 9;
    const CreaseField f = random_field(w, h, seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 20000; ++k) {
      const double x = -0.5 + (w + 1) * u(rng), y = -0.5 + (h + 1) * u(rng);
      const CreaseSample s = reconstruct_crease(f, x, y);
      ASSERT_TRUE(std::isfinite(s.distance) && s.distance >= 0.0);
      ASSERT_NEAR(std::hypot(s.gradient[0], s.gradient[1]), 1.0, 1e-9);
      ASSERT_NEAR(std::sqrt(s.normal[0] * s.normal[0] + s.normal[1] * s.normal[1] + s.normal[2] * s.normal[2]), 1.0,
                  1e-9);
    }
    // Distance: continuous across every interior cell edge, 0 at every crossing.
    for (uint32_t j = 1; j < f.cells_y(); ++j)
      for (uint32_t i = 1; i < f.cells_x(); ++i)
        for (int k = 0; k < 20; ++k) {
          const double t = u(rng), eps = 1e-12;         // slopes reach 3 texels / (1/1024) near a crossing by a corner
          const double xv = i - 0.5, yv = j - 0.5 + t;  // on the vertical edge x = i - 0.5
          EXPECT_NEAR(reconstruct_crease(f, xv - eps, yv).distance, reconstruct_crease(f, xv + eps, yv).distance, 1e-8);
          const double xh = i - 0.5 + t, yh = j - 0.5;  // on the horizontal edge y = j - 0.5
          EXPECT_NEAR(reconstruct_crease(f, xh, yh - eps).distance, reconstruct_crease(f, xh, yh + eps).distance, 1e-8);
        }
    for (uint32_t j = 0; j < f.samples_y(); ++j)
      for (uint32_t i = 0; i < f.cells_x(); ++i) {
        const float t = f.crossing_h[f.h_edge_index(i, j)];
        if (t == kCreaseNoCrossing) continue;
        const double x = i - 0.5 + t, y = j - 0.5;
        if (x > -0.5 && x < w + 0.5 && y > -0.5 && y < h + 0.5) {
          EXPECT_LE(reconstruct_crease(f, x, std::min(y + 1e-12, h + 0.5)).distance, 1e-9);
        }
      }
  }
}

// A cell whose two segments share the end point on the top edge (P0-P1 and P0-P2, case 3.1.3): the three
// regions each see only their own corners' normals.
TEST(CreaseConfigurations, SharedEndPointRegionsUseOnlyTheirCorners) {
  // A 2 x 2 map; its interior cell (1, 1) spans [0.5, 1.5]^2 with corners C0..C3 = texels (0,0), (1,0), (1,1),
  // (0,1), given four different normals.
  CreaseField f;
  f.allocate(2, 2);
  const float normals[4][3] = {{0.6f, 0.0f, 0.8f}, {-0.6f, 0.0f, 0.8f}, {0.0f, 0.6f, 0.8f}, {0.0f, -0.6f, 0.8f}};
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) f.normals[3 * k + c] = normals[k][c];
  for (size_t k = 0; k < f.distance.size(); ++k) f.distance[k] = 1.0f, f.gradient[2 * k] = 1.0f;
  f.crossing_h[f.h_edge_index(1, 1)] = 0.5f;               // top edge of cell (1, 1)
  f.crossing_v[f.v_edge_index(2, 1)] = 0.5f;               // right edge
  f.crossing_h[f.h_edge_index(1, 2)] = 0.5f;               // bottom edge
  f.segments[f.cell_index(1, 1)] = (1u << 0) | (1u << 4);  // P0-P1 and P0-P2
  // Regions: left of P0-P2 (x = 1): C0, C3; the corner cut off by P0-P1: C1; the rest: C2 only.
  const CreaseSample l = reconstruct_crease(f, 0.7, 1.0), corner = reconstruct_crease(f, 1.4, 0.6),
                     rest = reconstruct_crease(f, 1.3, 1.3);
  // Corner region (C1 only, texel (1, 0)): exactly its normal.
  EXPECT_NEAR(corner.normal[0], -0.6, 1e-7);  // stored as float
  EXPECT_NEAR(corner.normal[1], 0.0, 1e-9);
  // Left region: a mix of texels (0,0) = (0.6, 0, 0.8) and (0,1) = (0, 0.6, 0.8) only.
  EXPECT_GT(l.normal[0], 0.0);
  EXPECT_GT(l.normal[1], 0.0);
  // The rest (C2 only, texel (1, 1)): its normal (0, -0.6, 0.8) everywhere, including the shared end point's
  // side of the triangles around E.
  EXPECT_NEAR(rest.normal[0], 0.0, 1e-9);
  EXPECT_NEAR(rest.normal[1], -0.6, 1e-7);
}

}  // namespace
}  // namespace mbk
