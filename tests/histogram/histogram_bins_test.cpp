// The bins of the `histogram` asset (formats/histogram_layout.h): which bin a normal falls in, at the hard places:
// exactly on a theta or phi edge (the bin above), at the top edge pi/2 (the last bin), at the pole where phi is
// undefined (bin 0, for either sign of zero), and just below 2 pi. Checked against the stored edges themselves:
// every direction's bin [lo, hi) must hold its angle, computed here independently.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "formats/histogram_layout.h"
#include "libbake/core/hash.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(HistogramBins, ThetaOnAnEdgeIsInTheBinAbove) {
  const std::vector<double> edges = {0.0, 0.3, 0.9, kPi / 2};
  EXPECT_EQ(histogram_theta_bin(edges, 0.0), 0u);
  EXPECT_EQ(histogram_theta_bin(edges, std::nextafter(0.3, 0.0)), 0u);
  EXPECT_EQ(histogram_theta_bin(edges, 0.3), 1u);
  EXPECT_EQ(histogram_theta_bin(edges, std::nextafter(0.9, 0.0)), 1u);
  EXPECT_EQ(histogram_theta_bin(edges, 0.9), 2u);
  EXPECT_EQ(histogram_theta_bin(edges, kPi / 2), 2u);  // the horizon (repaired texels) is in the last bin
  const std::vector<double> one_bin = {0.0, kPi / 2};
  EXPECT_EQ(histogram_theta_bin(one_bin, 0.0), 0u);
  EXPECT_EQ(histogram_theta_bin(one_bin, kPi / 2), 0u);
}

TEST(HistogramBins, ThetaIsAccurateNearThePoleAndExactAtTheHorizon) {
  EXPECT_EQ(histogram_theta(0.0, 0.0, 1.0), 0.0);
  EXPECT_EQ(histogram_theta(1.0, 0.0, 0.0), kPi / 2);
  EXPECT_EQ(histogram_theta(0.6, -0.8, 0.0), kPi / 2);
  // acos(z) would give 0 here (z rounds to 1); the angle is 1e-9.
  EXPECT_NEAR(histogram_theta(1e-9, 0.0, 1.0), 1e-9, 1e-24);
}

TEST(HistogramBins, PhiAtThePoleIsBinZeroWhateverTheSignsOfZero) {
  for (double x : {0.0, -0.0})
    for (double y : {0.0, -0.0}) EXPECT_EQ(histogram_phi_bin(x, y, 32), 0u) << x << " " << y;
  const HistogramBins bins{{0.0, 0.2, kPi / 2}, 32};
  EXPECT_EQ(bins.bin_of(-0.0, -0.0, 1.0), 0u);
}

TEST(HistogramBins, PhiAxesAndWrap) {
  EXPECT_EQ(histogram_phi_bin(1.0, 0.0, 32), 0u);
  EXPECT_EQ(histogram_phi_bin(0.0, 1.0, 32), 8u);
  EXPECT_EQ(histogram_phi_bin(-1.0, 0.0, 32), 16u);
  EXPECT_EQ(histogram_phi_bin(-1.0, -0.0, 32), 16u);  // atan2 gives -pi, i.e. pi
  EXPECT_EQ(histogram_phi_bin(0.0, -1.0, 32), 24u);
  EXPECT_EQ(histogram_phi_bin(1.0, -1e-300, 32), 31u);  // rounds to 2 pi: the last bin
  EXPECT_EQ(histogram_phi_bin(1.0, -1e-300, 1), 0u);
  EXPECT_EQ(histogram_phi_bin(-1.0, 0.0, 2), 1u);  // pi: the edge of bin 1
}

// phi in [0, 2 pi] as the bins define it, computed without the library.
double reference_phi(double x, double y) {
  const double phi = std::atan2(y, x);
  return phi < 0.0 ? phi + 2.0 * kPi : phi;
}

void expect_phi_bin_holds(double x, double y, uint32_t n) {
  const std::vector<double> edges = histogram_phi_edges(n);
  const uint32_t bin = histogram_phi_bin(x, y, n);
  ASSERT_LT(bin, n);
  const double phi = reference_phi(x, y);
  EXPECT_LE(edges[bin], phi) << x << " " << y << " n " << n;
  if (bin + 1 < n) EXPECT_LT(phi, edges[bin + 1]) << x << " " << y << " n " << n;
}

TEST(HistogramBins, EveryPhiBinHoldsItsAngleOnTheEdgesAndAtRandom) {
  for (uint32_t n : {1u, 3u, 7u, 32u, 100u, 512u}) {
    const std::vector<double> edges = histogram_phi_edges(n);
    ASSERT_EQ(edges.size(), n + 1);
    EXPECT_EQ(edges[0], 0.0);
    EXPECT_EQ(edges[n], 2.0 * kPi);
    for (uint32_t i = 0; i < n; ++i) {
      EXPECT_LT(edges[i], edges[i + 1]);
      // Directions at the edge's angle and its neighbouring doubles.
      for (double a : {std::nextafter(edges[i], -1.0), edges[i], std::nextafter(edges[i], 10.0)})
        expect_phi_bin_holds(std::cos(a), std::sin(a), n);
    }
    for (uint32_t k = 0; k < 2000; ++k) {
      const double x = 2.0 * unit_from_hash(hash3(n, k, 1)) - 1.0, y = 2.0 * unit_from_hash(hash3(n, k, 2)) - 1.0;
      expect_phi_bin_holds(x, y, n);
    }
  }
}

TEST(HistogramBins, BinIndexIsThetaMajor) {
  const HistogramBins bins{{0.0, 0.2, 0.5, kPi / 2}, 4};
  EXPECT_EQ(bins.theta_bins(), 3u);
  EXPECT_EQ(bins.count(), 12u);
  const double t = 0.3;  // theta bin 1, phi = pi/2 + a little: phi bin 1
  EXPECT_EQ(bins.bin_of(std::sin(t) * std::cos(1.6), std::sin(t) * std::sin(1.6), std::cos(t)), 1u * 4 + 1);
  EXPECT_EQ(bins.bin_of(1.0, 0.0, 0.0), 2u * 4 + 0);
}

TEST(HistogramBins, TableSize) {
  // The paper's 4.8 GB: a 2048^2 map at 9 x 32 bins.
  EXPECT_EQ(histogram_table_bytes(2048, 2048, 288), 2049ull * 2049 * 288 * 4);
  EXPECT_GT(histogram_table_bytes(2048, 2048, 288), kHistogramMaxTableBytes);
  EXPECT_EQ(histogram_table_entries(1, 1, 1), 4u);
}

}  // namespace
}  // namespace mbk
