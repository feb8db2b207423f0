// Spherical EM for vMF mixtures (libbake/filter/vmf_mixture.h, [Han07] Alg. 7.1): recovery of mixtures sampled
// from known vMFs, the hard cases by name (identical normals, empty lobes, more lobes than distinct normals,
// overflow-free E-step at the kappa cap), the log-likelihood stopping rule, farthest-apart seeding, Eq. 7.25
// features and the Eq. 7.26 pull.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "libbake/core/vmf_lobe.h"
#include "libbake/filter/vmf_mixture.h"
#include "tests/filter/vmf_sampling.h"

namespace mbk {
namespace {

using test::sample_vmf;

Vec3 direction(double theta_deg, double phi_deg) {
  const double t = theta_deg * std::numbers::pi / 180, p = phi_deg * std::numbers::pi / 180;
  return Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

double angle_deg(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi;
}

struct TrueLobe {
  double alpha, kappa;
  Vec3 mu;
};

const std::vector<TrueLobe> kTruth = {{0.4, 60, direction(10, 0)},
                                      {0.3, 150, direction(35, 120)},
                                      {0.2, 400, direction(40, 240)},
                                      {0.1, 100, direction(40, 330)}};

std::vector<WeightedNormal> sample_mixture(int J, size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  double total = 0;
  for (int j = 0; j < J; ++j) total += kTruth[size_t(j)].alpha;
  std::vector<WeightedNormal> out;
  for (int j = 0; j < J; ++j) {
    const size_t count = size_t(std::llround(double(n) * kTruth[size_t(j)].alpha / total));
    for (size_t i = 0; i < count; ++i)
      out.push_back({sample_vmf(rng, kTruth[size_t(j)].mu, kTruth[size_t(j)].kappa), 0});
  }
  for (auto& x : out) x.w = 1.0 / double(out.size());
  return out;
}

// EM started from the farthest-apart of a few hundred sample normals taken as sharp lobes, as the pyramid
// seeds coarse texels from child lobes.
TEST(VmfMixture, RecoversSampledMixturesJ1To4) {
  for (int J = 1; J <= 4; ++J) {
    const auto normals = sample_mixture(J, 40000, 100 + J);
    std::vector<VmfComponent> candidates;
    for (size_t i = 0; i < normals.size(); i += 97) {
      VmfComponent c;
      c.alpha = 1.0, c.kappa = kVmfKappaMax, c.mu = normals[i].n, c.r = normals[i].n;
      candidates.push_back(c);
    }
    std::vector<VmfComponent> mixture = farthest_apart_seeds(candidates, J);
    const EmReport report = fit_vmf_mixture(normals, mixture, EmOptions{1e-9, 500});
    EXPECT_TRUE(report.converged) << "J = " << J;
    double total = 0;
    for (int j = 0; j < J; ++j) total += kTruth[size_t(j)].alpha;
    for (int j = 0; j < J; ++j) {
      const TrueLobe& t = kTruth[size_t(j)];
      const VmfComponent* best = nullptr;
      for (const VmfComponent& c : mixture)
        if (c.alpha > 0 && (!best || c.mu.dot(t.mu) > best->mu.dot(t.mu))) best = &c;
      ASSERT_NE(best, nullptr);
      EXPECT_LT(angle_deg(best->mu, t.mu), 1.0) << "J = " << J << " lobe " << j;
      EXPECT_NEAR(best->kappa, t.kappa, 0.05 * t.kappa) << "J = " << J << " lobe " << j;
      EXPECT_NEAR(best->alpha, t.alpha / total, 0.02) << "J = " << J << " lobe " << j;
    }
  }
}

TEST(VmfMixture, IdenticalNormalsCapKappa) {
  const std::vector<WeightedNormal> normals(64, WeightedNormal{direction(20, 45), 1.0 / 64});
  std::vector<VmfComponent> mixture(4);
  mixture[0].alpha = 1, mixture[0].kappa = 10, mixture[0].mu = Vec3::UnitZ();
  const EmReport report = fit_vmf_mixture(normals, mixture, EmOptions{});
  EXPECT_TRUE(report.converged);
  EXPECT_TRUE(std::isfinite(report.log_likelihood));
  EXPECT_EQ(mixture[0].alpha, 1.0);
  EXPECT_EQ(mixture[0].kappa, kVmfKappaMax);
  EXPECT_LT(angle_deg(mixture[0].mu, direction(20, 45)), 1e-6);
  for (int j = 1; j < 4; ++j) EXPECT_EQ(mixture[size_t(j)].alpha, 0.0);
}

TEST(VmfMixture, EmptyLobeIsEmptiedNotNaN) {
  std::vector<WeightedNormal> normals;
  std::mt19937_64 rng(5);
  for (int i = 0; i < 500; ++i) normals.push_back({sample_vmf(rng, Vec3::UnitZ(), 50), 1.0 / 500});
  std::vector<VmfComponent> mixture(2);
  mixture[0].alpha = 0.5, mixture[0].kappa = 50, mixture[0].mu = Vec3::UnitZ();
  mixture[1].alpha = 0.5, mixture[1].kappa = 1e5, mixture[1].mu = -Vec3::UnitZ();  // nothing anywhere near it
  fit_vmf_mixture(normals, mixture, EmOptions{});
  EXPECT_EQ(mixture[1].alpha, 0.0);
  EXPECT_EQ(mixture[1].r, Vec3::Zero());
  EXPECT_NEAR(mixture[0].alpha, 1.0, 1e-12);
  EXPECT_TRUE(std::isfinite(mixture[0].kappa));
}

// Both lobes at the cap and far from the normal: every exp(kappa (cos - 1)) underflows, the log-sum-exp does not.
TEST(VmfMixture, EStepHasNoOverflowOrUnderflowAtTheCap) {
  const std::vector<WeightedNormal> normals = {{Vec3::UnitZ(), 0.5}, {Vec3(0, 1, 0), 0.5}};
  std::vector<VmfComponent> mixture(2);
  mixture[0].alpha = 0.5, mixture[0].kappa = kVmfKappaMax, mixture[0].mu = Vec3::UnitX();
  mixture[1].alpha = 0.5, mixture[1].kappa = kVmfKappaMax, mixture[1].mu = -Vec3::UnitX();
  const EmReport report = fit_vmf_mixture(normals, mixture, EmOptions{1e-6, 1});
  EXPECT_TRUE(std::isfinite(report.log_likelihood));
  // log(0.5 g(0) + 0.5 g(0)) = log g(0), about -1e6: far below what exp can represent.
  EXPECT_NEAR(report.log_likelihood, vmf_log_density(kVmfKappaMax, 0.0), 1e-6);
  for (const VmfComponent& c : mixture) {
    EXPECT_NEAR(c.alpha, 0.5, 1e-12);
    EXPECT_TRUE(c.r.allFinite());
  }
}

TEST(VmfMixture, MoreLobesThanDistinctNormals) {
  std::vector<WeightedNormal> normals;
  for (int i = 0; i < 10; ++i) normals.push_back({direction(30, i % 2 ? 0 : 180), 0.1});
  std::vector<VmfComponent> candidates;
  for (const auto& n : normals) {
    VmfComponent c;
    c.alpha = 1, c.kappa = kVmfKappaMax, c.mu = n.n, c.r = n.n;
    candidates.push_back(c);
  }
  std::vector<VmfComponent> mixture = farthest_apart_seeds(candidates, 6);
  int seeded = 0;
  for (const auto& c : mixture) seeded += c.alpha > 0;
  EXPECT_EQ(seeded, 2);
  fit_vmf_mixture(normals, mixture, EmOptions{});
  int live = 0;
  double total = 0;
  for (const auto& c : mixture) {
    live += c.alpha > 0;
    total += c.alpha;
    EXPECT_TRUE(c.r.allFinite());
  }
  EXPECT_EQ(live, 2);
  EXPECT_NEAR(total, 1.0, 1e-15);
  EXPECT_NEAR(mixture[0].alpha, 0.5, 1e-12);
  EXPECT_EQ(mixture[0].kappa, kVmfKappaMax);
}

TEST(VmfMixture, SeedsAreFarthestApartLargestFirst) {
  std::vector<VmfComponent> c(5);
  const double alphas[5] = {0.1, 0.3, 0.2, 0.2, 0.2};
  const Vec3 dirs[5] = {direction(0, 0), direction(10, 0), direction(80, 0), direction(80, 180), direction(12, 5)};
  for (int i = 0; i < 5; ++i) c[size_t(i)].alpha = alphas[i], c[size_t(i)].mu = dirs[i], c[size_t(i)].kappa = 7 + i;
  const auto seeds = farthest_apart_seeds(c, 3);
  EXPECT_EQ(seeds[0].kappa, 8);   // largest amplitude first
  EXPECT_EQ(seeds[1].kappa, 10);  // 90 degrees from it (direction(80, 180)) is farthest
  EXPECT_EQ(seeds[2].kappa, 9);   // then direction(80, 0), 70 degrees from the first
  for (const auto& s : seeds) EXPECT_NEAR(s.alpha, 1.0 / 3, 1e-15);
}

TEST(VmfMixture, StopsOnLogLikelihoodChangeAndNeverDecreases) {
  const auto normals = sample_mixture(3, 6000, 9);
  std::vector<VmfComponent> start(3);
  for (int j = 0; j < 3; ++j) {
    start[size_t(j)].alpha = 1.0 / 3;
    start[size_t(j)].kappa = 20;
    start[size_t(j)].mu = (kTruth[size_t(j)].mu + Vec3(0.2, -0.1, 0.1)).normalized();
  }
  double previous = -INFINITY;
  for (int n = 1; n <= 12; ++n) {
    auto m = start;
    const EmReport r = fit_vmf_mixture(normals, m, EmOptions{0.0, n});
    EXPECT_GE(r.log_likelihood, previous - 1e-12) << n;
    previous = r.log_likelihood;
  }
  auto loose = start, tight = start;
  EmOptions loose_options{1.0, 1000}, tight_options{1e-10, 1000};
  loose_options.reseed = tight_options.reseed = false;  // the stopping rule of plain EM (no trial re-seeds)
  const EmReport a = fit_vmf_mixture(normals, loose, loose_options);
  const EmReport b = fit_vmf_mixture(normals, tight, tight_options);
  EXPECT_LE(a.iterations, 3);  // a gain below 1 nat stops it within a couple of steps
  EXPECT_TRUE(b.converged);
  EXPECT_GT(b.iterations, a.iterations);
  EXPECT_LT(b.iterations, 1000);
}

// SQUAREM (vmf_mixture.h) reaches the fixed point plain EM reaches, from the same start, in fewer E-steps: two
// overlapping lobes, where plain EM creeps.
TEST(VmfMixture, AccelerationReachesThePlainFixedPointSooner) {
  std::mt19937_64 rng(12);
  std::vector<WeightedNormal> normals;
  for (int i = 0; i < 3000; ++i) normals.push_back({sample_vmf(rng, direction(0, 0), 40), 0});
  for (int i = 0; i < 2000; ++i) normals.push_back({sample_vmf(rng, direction(12, 90), 80), 0});
  for (auto& x : normals) x.w = 1.0 / double(normals.size());
  std::vector<VmfComponent> start(2);
  start[0].alpha = start[1].alpha = 0.5;
  start[0].kappa = start[1].kappa = 10;
  start[0].mu = direction(20, 200), start[1].mu = direction(20, 20);
  EmOptions plain{1e-12, 100000}, accelerated{1e-12, 100000};
  plain.reseed = accelerated.reseed = false;
  plain.accelerate = false;
  auto a = start, b = start;
  const EmReport p = fit_vmf_mixture(normals, a, plain);
  const EmReport q = fit_vmf_mixture(normals, b, accelerated);
  ASSERT_TRUE(p.converged);
  ASSERT_TRUE(q.converged);
  EXPECT_GT(p.iterations, 100);  // slow enough to be worth accelerating
  EXPECT_LT(2 * q.iterations, p.iterations);
  EXPECT_GE(q.log_likelihood, p.log_likelihood - 1e-9);
  EXPECT_NEAR(vmf_mixture_log_likelihood(normals, b), vmf_mixture_log_likelihood(normals, a), 1e-6);
  for (size_t j = 0; j < 2; ++j) {
    const VmfComponent& x = a[j];
    const VmfComponent& y = b[0].mu.dot(x.mu) > b[1].mu.dot(x.mu) ? b[0] : b[1];
    EXPECT_NEAR(x.alpha, y.alpha, 1e-3);
    EXPECT_LT(angle_deg(x.mu, y.mu), 0.05);
    EXPECT_NEAR(x.kappa, y.kappa, 1e-2 * x.kappa);
  }
}

TEST(VmfMixture, FeaturesAreResponsibilityWeightedMeans) {
  std::vector<WeightedNormal> normals;
  std::vector<float> colours;
  for (int i = 0; i < 20; ++i) {
    normals.push_back({direction(40, i < 12 ? 0 : 180), 0.05});
    colours.push_back(i < 12 ? 1.0f : 0.0f);
    colours.push_back(i < 12 ? 0.25f : 0.75f);
  }
  std::vector<VmfComponent> mixture(2);
  mixture[0].alpha = mixture[1].alpha = 0.5;
  mixture[0].kappa = mixture[1].kappa = 100;
  mixture[0].mu = direction(40, 0), mixture[1].mu = direction(40, 180);
  fit_vmf_mixture(normals, mixture, EmOptions{});
  const auto y = lobe_features(normals, colours, 2, mixture);
  EXPECT_NEAR(mixture[0].alpha, 0.6, 1e-12);
  EXPECT_NEAR(y[0], 1.0, 1e-12);
  EXPECT_NEAR(y[1], 0.25, 1e-12);
  EXPECT_NEAR(y[2], 0.0, 1e-12);
  EXPECT_NEAR(y[3], 0.75, 1e-12);
}

// The collapse of issue 16, in one texel: three tight clusters and one far outlying normal, started as the pyramid
// starts a coarse texel (farthest-apart seeds among single-normal lobes at the cap), so one seed is the
// outlier. Without the guard its lobe stays a spike of amplitude 1/N on it and two clusters share a lobe; with
// it no lobe is spent on the outlier, each cluster has its own, and the likelihood is higher.
TEST(VmfMixture, OutlierGetsNoLobe) {
  std::mt19937_64 rng(11);
  const Vec3 centres[3] = {direction(15, 0), direction(30, 120), direction(30, 240)}, outlier = direction(85, 60);
  std::vector<WeightedNormal> normals;
  for (const Vec3& c : centres)
    for (int i = 0; i < 300; ++i) normals.push_back({sample_vmf(rng, c, 300), 0});
  normals.push_back({outlier, 0});
  for (auto& n : normals) n.w = 1.0 / double(normals.size());
  std::vector<VmfComponent> candidates;
  for (const auto& n : normals) {
    VmfComponent c;
    c.alpha = 1, c.kappa = kVmfKappaMax, c.mu = n.n, c.r = n.n;
    candidates.push_back(c);
  }
  const std::vector<VmfComponent> seeds = farthest_apart_seeds(candidates, 3);
  ASSERT_LT(angle_deg(seeds[1].mu, outlier), 1e-9);  // the outlier is a seed: the trap is set
  auto guarded = seeds, unguarded = seeds;
  const EmReport with = fit_vmf_mixture(normals, guarded, EmOptions{});
  EmOptions off;
  off.reseed = false;
  const EmReport without = fit_vmf_mixture(normals, unguarded, off);
  EXPECT_NEAR(unguarded[1].alpha, 1.0 / double(normals.size()), 1e-9);  // the collapse, reproduced
  EXPECT_EQ(unguarded[1].kappa, kVmfKappaMax);
  EXPECT_GE(with.reseeds, 1);
  for (const VmfComponent& c : guarded) {
    EXPECT_GT(c.alpha, 0.2);
    EXPECT_GT(angle_deg(c.mu, outlier), 20.0);
  }
  for (const Vec3& centre : centres) {
    double nearest = 180;
    for (const VmfComponent& c : guarded) nearest = std::min(nearest, angle_deg(c.mu, centre));
    EXPECT_LT(nearest, 1.0);
  }
  EXPECT_GT(with.log_likelihood, without.log_likelihood + 0.5);
  EXPECT_NEAR(with.log_likelihood, vmf_mixture_log_likelihood(normals, guarded), 1e-6);
}

// A trial re-seed is kept only when it ends higher: whatever the start, the guarded fit is never below the
// unguarded one from the same start. Here a small genuine lobe (2 identical normals of 300, the weakest lobe)
// is worth keeping at the cap: re-seeds are tried and the lobe survives.
TEST(VmfMixture, GuardNeverLowersTheLikelihood) {
  std::mt19937_64 rng(4);
  std::vector<WeightedNormal> normals;
  for (int i = 0; i < 298; ++i) normals.push_back({sample_vmf(rng, direction(10, 0), 80), 0});
  for (int i = 0; i < 2; ++i) normals.push_back({direction(50, 200), 0});
  for (auto& n : normals) n.w = 1.0 / double(normals.size());
  for (int J : {2, 3}) {
    std::vector<VmfComponent> start(static_cast<size_t>(J));
    for (int j = 0; j < J; ++j) start[size_t(j)].alpha = 1.0 / J, start[size_t(j)].kappa = 50;
    start[0].mu = direction(10, 0), start[1].mu = direction(50, 200);
    if (J == 3) start[2].mu = direction(20, 90);
    auto guarded = start, unguarded = start;
    EmOptions off;
    off.reseed = false;
    const double with = fit_vmf_mixture(normals, guarded, EmOptions{}).log_likelihood;
    const double without = fit_vmf_mixture(normals, unguarded, off).log_likelihood;
    EXPECT_GE(with, without - 1e-9) << "J " << J;
    EXPECT_NEAR(guarded[1].alpha, 2.0 / 300, 1e-6) << "J " << J;  // the genuine small lobe is kept
  }
}

// Eq. (7.26): with C > 0 the lobe direction moves from r / |r| towards the neighbour target, by the formula.
TEST(VmfMixture, AlignmentPullsDirectionByEquation726) {
  std::mt19937_64 rng(2);
  std::vector<WeightedNormal> normals;
  for (int i = 0; i < 400; ++i) normals.push_back({sample_vmf(rng, Vec3::UnitZ(), 30), 1.0 / 400});
  std::vector<VmfComponent> free(1), pulled(1);
  free[0].alpha = pulled[0].alpha = 1, free[0].kappa = pulled[0].kappa = 30;
  const std::vector<Vec3> target = {0.8 * direction(30, 90)};
  fit_vmf_mixture(normals, free, EmOptions{1e-9, 50});
  fit_vmf_mixture(normals, pulled, EmOptions{1e-9, 50, kVmfKappaMax, 0.5}, target);
  EXPECT_LT(angle_deg(free[0].mu, free[0].r), 1e-9);
  EXPECT_LT(angle_deg(pulled[0].mu, (pulled[0].r + 0.5 * target[0]).normalized()), 1e-9);
  EXPECT_GT(angle_deg(pulled[0].mu, free[0].mu), 1.0);
}

}  // namespace
}  // namespace mbk
