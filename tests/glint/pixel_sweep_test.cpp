// The pixel cut into sub-pixel cells for the half vector's sweep (libbake/glint/pixel_sweep.h): a flat map's
// highlight averaged over the cells, each a Gaussian footprint of its own box's deviation under the slope field
// (on a flat map: N(s_cell; n, sigma_r^2 I + S_cell S_cell^T / 12), glint_pndf.h and
// GlintPndf.ConstantExampleWithASlopeFieldIsTheHighlightsFootprintAverage), must be the box pixel's average, for
// sweeps from none to 30 sigma_r per step, correlated and grazing; the cells' count follows the stated limits;
// non-finite steps give one cell.
#include "libbake/glint/pixel_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace mbk {
namespace {

double gaussian(const Vec2& d, const Mat2& c) {
  return std::exp(-0.5 * d.dot(c.inverse() * d)) / (2 * std::numbers::pi * std::sqrt(c.determinant()));
}

// The box pixel's average of N(s + steps x; n, sigma_r^2 I), x uniform in [-1/2, 1/2]^2 (a 200 x 200 midpoint
// rule), against the cells' mean. Relative to the Gaussian's peak (the narrow highlight's brightness), over random
// steps and normals near the sweep: <= 2% (the stated ripple is 1.4%). One Gaussian footprint over the whole pixel
// misses by far more on the same cases (printed).
TEST(PixelSweep, CellsAverageLikeTheBoxPixel) {
  const double sigma_r = 0.01;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0, worst_gaussian = 0.0;
  for (int k = 0; k < 300; ++k) {
    Mat2 steps;
    const double a = 2 * std::numbers::pi * unit(rng);
    steps.col(0) = 30 * sigma_r * unit(rng) * Vec2(std::cos(a), std::sin(a));
    steps.col(1) = 4 * sigma_r * unit(rng) * Vec2(-std::sin(a + 0.3), std::cos(a + 0.3));
    const Vec2 s(0.1, -0.2);
    const Vec2 n =
        s + steps * Vec2(unit(rng) - 0.5, unit(rng) - 0.5) + sigma_r * Vec2(unit(rng) - 0.5, unit(rng) - 0.5);
    const Mat2 c = sigma_r * sigma_r * Mat2::Identity();
    double box = 0.0;
    constexpr int kSteps = 200;
    for (int j = 0; j < kSteps; ++j)
      for (int i = 0; i < kSteps; ++i)
        box += gaussian(s + steps * Vec2((i + 0.5) / kSteps - 0.5, (j + 0.5) / kSteps - 0.5) - n, c);
    box /= kSteps * kSteps;
    const std::array<int, 2> m = pixel_sweep_cells(steps, sigma_r);
    Mat2 cell_steps = steps;
    cell_steps.col(0) /= m[0];
    cell_steps.col(1) /= m[1];
    double cells = 0.0;
    for (int j = 0; j < m[1]; ++j)
      for (int i = 0; i < m[0]; ++i)
        cells += gaussian(s + steps * Vec2((i + 0.5) / m[0] - 0.5, (j + 0.5) / m[1] - 0.5) - n,
                          c + cell_steps * cell_steps.transpose() / 12.0);
    cells /= m[0] * m[1];
    const double one_gaussian = gaussian(s - n, c + steps * steps.transpose() / 12.0);
    const double peak = gaussian(Vec2::Zero(), c);
    worst = std::max(worst, std::abs(cells - box) / peak);
    worst_gaussian = std::max(worst_gaussian, std::abs(one_gaussian - box) / peak);
  }
  std::printf("[ info ] worst |cells - box| %.4f of the peak; one Gaussian over the pixel %.4f\n", worst,
              worst_gaussian);
  EXPECT_LE(worst, 0.02);
  EXPECT_GT(worst_gaussian, 5 * worst);
}

TEST(PixelSweep, CellCountsAndLimits) {
  const double sigma_r = 0.01;
  Mat2 steps = Mat2::Zero();
  EXPECT_EQ(pixel_sweep_cells(steps, sigma_r), (std::array<int, 2>{1, 1}));  // no sweep: one cell
  steps.col(0) = Vec2(0.05, 0.0);                                            // 5 sigma_r: 3 cells of 1.67 sigma_r
  EXPECT_EQ(pixel_sweep_cells(steps, sigma_r), (std::array<int, 2>{3, 1}));
  steps.col(1) = Vec2(0.0, 1.0);  // 100 sigma_r: capped at 8 cells
  EXPECT_EQ(pixel_sweep_cells(steps, sigma_r), (std::array<int, 2>{3, 8}));
  steps.col(0) = Vec2(1.0, 0.0);  // both capped: at most kMaxSweepCellsPerPixel
  const std::array<int, 2> both = pixel_sweep_cells(steps, sigma_r);
  EXPECT_LE(both[0] * both[1], kMaxSweepCellsPerPixel);
  EXPECT_GE(both[0] * both[1], kMaxSweepCellsPerPixel / 2);
  steps(0, 0) = INFINITY;
  EXPECT_EQ(pixel_sweep_cells(steps, sigma_r), (std::array<int, 2>{1, 1}));
}

}  // namespace
}  // namespace mbk
