// The multi-start reference EM (libbake/filter/vmf_reference_fit.h) and the pyramid's fits measured against it:
// the reference reaches the likelihood of the true parameters on sampled mixtures (a maximum-likelihood fit can
// only be higher), handles identical normals at the cap, is deterministic, and the pyramid's levels on generated
// maps are within 0.05 nats per finest normal of it at every level, and the fast fit (chunks at coarse levels,
// SQUAREM) is no worse per level than the exact plain EM it replaced, on generated and real maps (issue 16).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "libbake/core/vmf_lobe.h"
#include "libbake/filter/vmf_pyramid.h"
#include "libbake/filter/vmf_reference_fit.h"
#include "libbake/gen/generator.h"
#include "tests/filter/vmf_sampling.h"
#include "tests/real_normal_maps.h"

namespace mbk {
namespace {

Vec3 direction(double theta_deg, double phi_deg) {
  const double t = theta_deg * std::numbers::pi / 180, p = phi_deg * std::numbers::pi / 180;
  return Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

using test::sample_vmf;

TEST(VmfReferenceFit, ReachesTheTrueParametersLikelihood) {
  std::mt19937_64 rng(3);
  std::vector<VmfComponent> truth(3);
  const double alphas[3] = {0.5, 0.3, 0.2}, kappas[3] = {40, 120, 300};
  const Vec3 mus[3] = {direction(10, 0), direction(40, 100), direction(45, 250)};
  std::vector<WeightedNormal> normals;
  for (int j = 0; j < 3; ++j) {
    truth[size_t(j)].alpha = alphas[j], truth[size_t(j)].kappa = kappas[j], truth[size_t(j)].mu = mus[j];
    for (int i = 0; i < int(4000 * alphas[j]); ++i) normals.push_back({sample_vmf(rng, mus[j], kappas[j]), 0});
  }
  for (auto& n : normals) n.w = 1.0 / double(normals.size());
  VmfReferenceOptions options;
  options.lobes = 3;
  const VmfReferenceFit fit = multi_start_vmf_fit(normals, options);
  const double truth_ll = vmf_mixture_log_likelihood(normals, truth);
  EXPECT_GE(fit.log_likelihood, truth_ll - 1e-9);
  EXPECT_LT(fit.log_likelihood, truth_ll + 0.01);  // 4000 samples: the fit cannot be much better than the truth
  EXPECT_NEAR(fit.log_likelihood, vmf_mixture_log_likelihood(normals, fit.mixture), 1e-9);
  EXPECT_EQ(multi_start_vmf_fit(normals, options).log_likelihood, fit.log_likelihood);  // deterministic
}

TEST(VmfReferenceFit, IdenticalNormalsGiveOneLobeAtTheCap) {
  const std::vector<WeightedNormal> normals(50, WeightedNormal{direction(30, 60), 1.0 / 50});
  const VmfReferenceFit fit = multi_start_vmf_fit(normals, VmfReferenceOptions{});
  ASSERT_EQ(fit.mixture.size(), 1u);
  EXPECT_NEAR(fit.mixture[0].alpha, 1.0, 1e-12);
  EXPECT_EQ(fit.mixture[0].kappa, kVmfKappaMax);
  EXPECT_NEAR(fit.log_likelihood, vmf_log_density(kVmfKappaMax, 1.0), 1e-6);
}

// Every level >= 1 of every generated kind at 64 x 64, every texel: the mean log-likelihood per finest normal
// of the stored lobes is within 0.05 nats of the 3-start reference (issue 16; the largest gap is 0.04, and the
// pyramid is above the reference on many levels: tests/bench/vmf_fit_bench.cpp prints them).
TEST(VmfReferenceFit, PyramidLevelsWithinReferenceOnGeneratedMaps) {
  for (const GeneratorKind& kind : generator_kinds()) {
    const NormalMap map = generate_normal_map(kind.name, MapSize{64, 64}, 1, Progress::silent());
    const VmfPyramid p = build_vmf_pyramid(map, nullptr, VmfBakeOptions{}, Progress::silent());
    for (size_t k = 1; k < p.levels.size(); ++k) {
      const VmfLevel& level = p.levels[k];
      double fit = 0.0, reference = 0.0;
      for (uint32_t j = 0; j < level.height; ++j)
        for (uint32_t i = 0; i < level.width; ++i) {
          const auto normals = vmf_texel_normals(map, level.width, level.height, i, j);
          std::vector<VmfComponent> stored;
          for (int l = 0; l < p.lobes; ++l)
            stored.push_back(
                decode_lobe(&level.lobes[((size_t(j) * level.width + i) * p.lobes + size_t(l)) * 4], kVmfKappaMax));
          fit += vmf_mixture_log_likelihood(normals, stored);
          reference += multi_start_vmf_fit(normals, VmfReferenceOptions{}).log_likelihood;
        }
      const double texels = double(level.width) * level.height;
      EXPECT_NEAR(fit / texels, level.statistics.mean_log_likelihood, 1e-9) << kind.name << " level " << k;
      EXPECT_GE(fit / texels, reference / texels - 0.05) << kind.name << " level " << k;
    }
  }
}

// The bake's fit against the one before issue 16's speed work, every start and guard trial by plain EM on every
// finest normal (max_chunks 0, no acceleration): per level, the mean log-likelihood per finest normal of the
// stored lobes. Both reach local optima by different paths, so either can be ahead on a level: the largest
// shortfall measured is 0.0023 nats (flakes, 128 x 128), and the gains reach 0.018 (scratches).
void expect_no_worse_than_exact_plain_fit(const NormalMap& map, const std::string& name) {
  VmfBakeOptions exact;
  exact.max_chunks = 0;
  exact.em.accelerate = false;
  const VmfPyramid fast = build_vmf_pyramid(map, nullptr, VmfBakeOptions{}, Progress::silent());
  const VmfPyramid slow = build_vmf_pyramid(map, nullptr, exact, Progress::silent());
  double total = 0.0;
  for (size_t k = 1; k < fast.levels.size(); ++k) {
    const double gain = fast.levels[k].statistics.mean_log_likelihood - slow.levels[k].statistics.mean_log_likelihood;
    EXPECT_GE(gain, -0.005) << name << " level " << k;
    total += gain;
  }
  EXPECT_GE(total, -0.005) << name;
}

// 128 x 128: the two coarsest levels (4096 and 16384 normals per texel) are fitted on chunks.
TEST(VmfReferenceFit, FastFitNoWorseThanExactPlainFitOnGeneratedMaps) {
  for (const GeneratorKind& kind : generator_kinds())
    expect_no_worse_than_exact_plain_fit(generate_normal_map(kind.name, MapSize{128, 128}, 1, Progress::silent()),
                                         std::string(kind.name));
}

// The central 128 x 128 of each real map (8- and 16-bit: many identical normals, chunks mostly exact).
TEST(VmfReferenceFit, FastFitNoWorseThanExactPlainFitOnRealMaps) {
  const int maps = test::for_each_real_normal_map([](const NormalMap& map, const std::string& name) {
    NormalMap crop;
    crop.width = crop.height = 128;
    for (uint32_t y = 0; y < 128; ++y)
      for (uint32_t x = 0; x < 128; ++x)
        crop.texels.push_back(map.at((map.width - 128) / 2 + x, (map.height - 128) / 2 + y));
    expect_no_worse_than_exact_plain_fit(crop, name);
  });
  if (maps == 0) GTEST_SKIP() << "no real normal maps beside the repository";
}

}  // namespace
}  // namespace mbk
