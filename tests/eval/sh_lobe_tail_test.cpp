// The SH bands beyond the stored order, completed from a vMF lobe (libbake/eval/sh_lobe_tail.h). For one normal
// (kappa = inf) the stored bands plus the tail are the lobe's whole series: the closed-form microfacet D itself.
// For a vMF NDF they are the whole convolution series, summed here band by band without the table.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "libbake/core/sh_basis.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/eval/filtered_ndf_shading.h"
#include "libbake/eval/sh_lobe_tail.h"

namespace mbk {
namespace {

// sum_{l <= order} rhat_l Lambda_l (2l + 1) / (4 pi) P_l(t): a zonal NDF's stored bands (or, to a high order, all).
double zonal_series(const std::vector<double>& rhat, const std::vector<double>& lambda, int order, double t) {
  std::vector<double> y(size_t(order) + 1);
  zonal_harmonics(order, t, y);  // Y_l0(t) = sqrt((2l + 1) / (4 pi)) P_l(t)
  double sum = 0.0;
  for (int l = 0; l <= order; ++l)
    sum += rhat[size_t(l)] * lambda[size_t(l)] * std::sqrt((2 * l + 1) / (4 * std::numbers::pi)) * y[size_t(l)];
  return sum;
}

TEST(ShLobeTail, OneNormalGivesTheClosedFormLobe) {
  for (const MicrofacetLobe lobe :
       {MicrofacetLobe{Distribution::ggx, 0.1}, MicrofacetLobe{Distribution::beckmann, 0.3}})
    for (const int order : {0, 2, 8, 16}) {
      const ShLobeTail tail(lobe, order);
      const std::vector<double> rhat = microfacet_rhat(lobe, order);
      const std::vector<double> ones(size_t(order) + 1, 1.0);
      const double peak = microfacet_d(lobe, 1.0);
      for (double angle = 0.0; angle < 1.5; angle += 0.013) {
        const double t = std::cos(angle);
        const double completed = zonal_series(rhat, ones, order, t) + tail.value(t, INFINITY);
        EXPECT_NEAR(completed, microfacet_d(lobe, t), 0.01 * peak) << lobe.alpha << " " << order << " " << angle;
      }
    }
}

TEST(ShLobeTail, VmfNdfGivesTheWholeConvolutionSeries) {
  const MicrofacetLobe lobe{Distribution::ggx, 0.15};
  const int order = 4, top = 400;
  const ShLobeTail tail(lobe, order);
  const std::vector<double> rhat = microfacet_rhat(lobe, top);
  for (const double kappa : {0.5, 5.0, 50.0, 500.0, 5e4}) {
    std::vector<double> lambda(size_t(top) + 1);
    vmf_band_factors(kappa, lambda);
    const double scale = zonal_series(rhat, lambda, top, 1.0);
    for (double angle = 0.0; angle < 3.1; angle += 0.05) {
      const double t = std::cos(angle);
      const double completed = zonal_series(rhat, lambda, order, t) + tail.value(t, kappa);
      EXPECT_NEAR(completed, zonal_series(rhat, lambda, top, t), 0.01 * scale) << kappa << " " << angle;
    }
  }
  // Broad NDFs keep nothing beyond the order; kappa below the table is the first row, never NaN.
  EXPECT_NEAR(tail.value(0.3, 1e-3), 0.0, 1e-9);
  EXPECT_TRUE(std::isfinite(tail.value(1.0, 0.0)));
}

}  // namespace
}  // namespace mbk
