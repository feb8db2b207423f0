// Footprint statistics of fractal gradient noise (libbake/colormap/noise_statistics.h): the closed-form second
// moments of one octave (point variance, box-mean variance, box-centre covariance) against brute force over the
// actual noise (dense box sampling at many lattice positions, i.e. many hashed gradients); the table against the
// direct computation; the limits (point, huge boxes); and the fBm filtering distribution against supersampled
// footprints of periodic_fbm.
#include <gtest/gtest.h>

#include <cmath>

#include "libbake/colormap/noise_statistics.h"
#include "libbake/core/hash.h"
#include "libbake/gen/periodic_noise.h"

namespace mbk {
namespace {

struct Sampled {
  double box_mean_variance = 0, centre_covariance = 0, point_variance = 0;
};

// Averages over 48 x 48 box positions spread over a 64 x 64-cell lattice; each box mean by 24 x 24 midpoints.
Sampled sample_octave(double w1, double w2) {
  constexpr uint32_t P = 64;
  constexpr int positions = 48, S = 24;
  Sampled s;
  for (int i = 0; i < positions; ++i)
    for (int j = 0; j < positions; ++j) {
      const double x0 = std::fmod(i * 1.6180339887 * P / positions, P),
                   y0 = std::fmod(j * 2.4142135624 * P / positions, P);
      const double n = periodic_gradient_noise(x0 + 0.5 * w1, y0 + 0.5 * w2, P, P, 7);
      double b = 0.0;
      for (int a = 0; a < S; ++a)
        for (int c = 0; c < S; ++c)
          b += periodic_gradient_noise(x0 + (a + 0.5) * w1 / S, y0 + (c + 0.5) * w2 / S, P, P, 7);
      b /= S * S;
      s.box_mean_variance += b * b, s.centre_covariance += b * n, s.point_variance += n * n;
    }
  const double count = positions * positions;
  s.box_mean_variance /= count, s.centre_covariance /= count, s.point_variance /= count;
  return s;
}

TEST(NoiseStatistics, OctaveMomentsMatchTheActualNoise) {
  const NoiseFootprintTable table;
  for (const auto& [w1, w2] : {std::pair{0.1, 0.1}, {0.5, 0.5}, {1.0, 1.0}, {2.0, 0.5}, {3.0, 3.0}}) {
    const Sampled s = sample_octave(w1, w2);
    // Sampling 2304 positions of a hashed process: a few percent of V.
    const double tolerance = 0.04 * table.point_variance();
    EXPECT_NEAR(table.point_variance(), s.point_variance, tolerance);
    EXPECT_NEAR(table.box_mean_variance(w1, w2), s.box_mean_variance, tolerance) << w1 << "x" << w2;
    EXPECT_NEAR(table.box_centre_covariance(w1, w2), s.centre_covariance, tolerance) << w1 << "x" << w2;
  }
}

TEST(NoiseStatistics, TableMatchesDirectComputation) {
  const NoiseFootprintTable table;
  for (double w : {0.003, 0.37, 1.0, 2.9, 17.0, 200.0}) {
    const auto t = table.axis(w), e = NoiseFootprintTable::axis_exact(w);
    EXPECT_NEAR(t.a, e.a, 2e-3 * NoiseFootprintTable::axis_exact(0).a) << w;
    EXPECT_NEAR(t.b, e.b, 2e-3 * NoiseFootprintTable::axis_exact(0).b) << w;
    EXPECT_NEAR(t.a_centre, e.a_centre, 2e-3 * NoiseFootprintTable::axis_exact(0).a) << w;
    EXPECT_NEAR(t.b_centre, e.b_centre, 2e-3 * NoiseFootprintTable::axis_exact(0).b) << w;
  }
}

TEST(NoiseStatistics, PointLimitAndHugeBoxes) {
  const NoiseFootprintTable table;
  const double V = table.point_variance();
  EXPECT_NEAR(table.box_mean_variance(1e-6, 1e-6), V, 1e-6 * V);
  EXPECT_NEAR(table.box_centre_covariance(0.0, 0.0), V, 1e-12);
  // Beyond 4 cells the centre value says nothing about the box mean; the box mean's variance falls like 1/w^3.
  EXPECT_EQ(NoiseFootprintTable::axis_exact(4.5).a_centre, 0.0);
  EXPECT_NEAR(NoiseFootprintTable::axis_exact(4.5).b_centre, 1.0 / 4.5, 1e-14);
  EXPECT_EQ(table.box_centre_covariance(1e4, 1e4), 0.0);
  const double big = table.box_mean_variance(1000.0, 1000.0), bigger = table.box_mean_variance(2000.0, 2000.0);
  EXPECT_NEAR(big / bigger, 8.0, 0.1);
  EXPECT_TRUE(std::isfinite(table.box_mean_variance(1e300, 1e300)));
}

TEST(NoiseStatistics, FbmFootprintMatchesSupersampledFootprints) {
  // Over many footprints of a given size, the filtered colour depends on the law of f in the footprint; check that
  // our N(mean, variance) has the same second-moment budget as the supersampled truth: E[(mean - true mean)^2] +
  // E[true variance] == E[variance] + ... here: the predicted mean tracks the true footprint mean, and the
  // predicted variance equals the average of (f - predicted mean)^2 over the footprint samples.
  const NoiseFootprintTable table;
  NoiseParameters noise;
  noise.cells_x = 8, noise.cells_y = 8, noise.octaves = 5, noise.gain = 0.55, noise.seed = 3;
  for (double box : {0.002, 0.01, 0.05, 0.2}) {
    double predicted_variance = 0, measured = 0, mean_error = 0, mean_spread = 0;
    constexpr int footprints = 300, S = 32;
    for (int k = 0; k < footprints; ++k) {
      const Vec2 centre(std::fmod(0.5 + k * 0.6180339887, 1.0), std::fmod(0.25 + k * 0.7548776662, 1.0));
      const NoiseFootprint f = fbm_footprint(table, noise, centre, Vec2(box, box));
      double true_mean = 0, spread = 0;
      for (int a = 0; a < S; ++a)
        for (int b = 0; b < S; ++b) {
          const Vec2 p = centre + box * Vec2((a + 0.5) / S - 0.5, (b + 0.5) / S - 0.5);
          const double v = periodic_fbm(p, noise.cells_x, noise.cells_y, noise.octaves, noise.gain, noise.seed);
          true_mean += v, spread += (v - f.mean) * (v - f.mean);
        }
      true_mean /= S * S;
      predicted_variance += f.variance, measured += spread / (S * S);
      mean_error += (f.mean - true_mean) * (f.mean - true_mean), mean_spread += true_mean * true_mean;
    }
    // The variance budget holds on average (within the sampling of 300 footprints).
    EXPECT_NEAR(predicted_variance / footprints, measured / footprints, 0.12 * measured / footprints) << box;
    // The predicted mean explains most of the footprint means when footprints are small.
    if (box <= 0.01) {
      EXPECT_LT(mean_error, 0.1 * mean_spread) << box;
    }
  }
}

}  // namespace
}  // namespace mbk
