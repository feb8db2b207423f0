// The band radiance grid (libbake/eval/band_radiance_grid.h): a lookup equals the direct SH sum
// sum_lm Lambda_l L_lm Y_lm(r) within the interpolation bound, for random lighting whose every band is as strong as
// band 0 (the worst case for interpolation), lobes from the narrowest an order resolves to broad ones, directions
// anywhere including the poles and the phi seam; and exactly at grid nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "libbake/core/sh_basis.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/eval/band_radiance_grid.h"
#include "libbake/eval/sh_lighting.h"
#include "libbake/histogram/roughness_zh_table.h"

namespace mbk {
namespace {

Vec3 direct_sum(const std::vector<Vec3>& sh, const ShBasisEvaluator& basis, const Vec3& r,
                const std::vector<double>& lambda) {
  std::vector<double> y(size_t(basis.count()));
  basis.evaluate(r, y);
  Vec3 sum = Vec3::Zero();
  for (int l = 0; l <= basis.order(); ++l)
    for (int m = -l; m <= l; ++m) sum += lambda[size_t(l)] * y[size_t(sh_index(l, m))] * sh[size_t(sh_index(l, m))];
  return sum;
}

TEST(BandRadianceGrid, LookupsMatchTheDirectSum) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  for (const int order : {4, 20, 40}) {
    std::vector<Vec3> sh(size_t(sh_count(order)));
    for (Vec3& c : sh) c = Vec3(normal(rng), normal(rng), normal(rng));
    const BandRadianceGrid grid(sh);
    const ShBasisEvaluator basis(order);
    for (const double sigma : {narrowest_resolved_roughness(order), 0.05, 0.3}) {
      std::vector<double> lambda(size_t(order) + 1);
      vmf_band_factors(1.0 / (4.0 * sigma * sigma), lambda);
      // The bound: band l errs at most (pi l / (4 L))^2 / 8 of its largest value, which is at most
      // sqrt((2l + 1) / (4 pi)) times the norm of its coefficients (the addition theorem).
      double bound = 0.0;
      for (int l = 1; l <= order; ++l) {
        double norm2 = 0.0;
        for (int m = -l; m <= l; ++m) norm2 += sh[size_t(sh_index(l, m))].squaredNorm() / 3.0;
        const double step = std::numbers::pi * l / (4.0 * order);
        bound += lambda[size_t(l)] * step * step / 8.0 * std::sqrt((2.0 * l + 1.0) / (4.0 * std::numbers::pi) * norm2);
      }
      double worst = 0.0;
      for (int i = 0; i < 2000; ++i) {
        Vec3 r = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
        if (i == 0) r = Vec3::UnitY();
        if (i == 1) r = -Vec3::UnitY();
        if (i == 2) r = Vec3(1, 0, -1e-17).normalized();  // phi just below 2 pi: the seam
        worst =
            std::max(worst, (grid.lobe_radiance(r, lambda) - direct_sum(sh, basis, r, lambda)).cwiseAbs().maxCoeff());
      }
      std::printf("[ info ] order %d, sigma %.4f: largest error %.3g, bound %.3g\n", order, sigma, worst, bound);
      EXPECT_LE(worst, bound + 1e-5) << order << " " << sigma;
    }
    // At a grid node (theta = 0: the pole; phi = 0 on the equator) the lookup is the stored sum itself (float).
    std::vector<double> ones(size_t(order) + 1, 1.0);
    for (const Vec3& node : {Vec3(0, 1, 0), Vec3(1, 0, 0)}) {
      const Vec3 expected = direct_sum(sh, basis, node, ones);
      EXPECT_LT((grid.lobe_radiance(node, ones) - expected).cwiseAbs().maxCoeff(), 1e-5 * (1.0 + expected.norm()));
    }
  }
}

}  // namespace
}  // namespace mbk
