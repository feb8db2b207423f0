// The vectorised E-step (libbake/filter/vmf_e_step.h) against a brute-force one in long double with std::exp and
// std::log, on the hard cases (identical normals at the kappa cap, antipodal normals, one normal, one lobe, empty
// lobes between live ones, counts that are not a multiple of the lanes, several chunks), its two instruction
// paths against each other (bit-identical), and a scalar loop in the documented summation order (bit-identical: the
// blocks the vector loop keeps in flight do not change the sums).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "libbake/core/fast_exp_log.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/filter/vmf_e_step.h"

namespace mbk {
namespace {

struct BruteSums {
  std::vector<long double> mass;
  std::vector<Vec3> moment;
  long double log_likelihood = 0;
};

// Straight from the definitions, without the log-domain shortcut: each term log(alpha_j g_j(n)) in full.
BruteSums brute_e_step(const std::vector<WeightedNormal>& normals, const std::vector<VmfComponent>& mixture) {
  BruteSums b;
  b.mass.assign(mixture.size(), 0);
  b.moment.assign(mixture.size(), Vec3::Zero());
  for (const WeightedNormal& wn : normals) {
    std::vector<long double> log_term(mixture.size(), -INFINITY);
    long double top = -INFINITY;
    for (size_t j = 0; j < mixture.size(); ++j) {
      if (mixture[j].alpha <= 0.0) continue;
      log_term[j] = std::log((long double)mixture[j].alpha) + vmf_log_density(mixture[j].kappa, 1.0) +
                    (long double)mixture[j].kappa * ((long double)mixture[j].mu.dot(wn.n) - 1);
      top = std::max(top, log_term[j]);
    }
    long double sum = 0;
    for (long double l : log_term) sum += std::exp(l - top);
    b.log_likelihood += wn.w * (top + std::log(sum));
    for (size_t j = 0; j < mixture.size(); ++j) {
      const long double z = std::exp(log_term[j] - top) / sum;
      b.mass[j] += wn.w * z;
      b.moment[j] += double(wn.w * z) * wn.n;
    }
  }
  return b;
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 v(g(rng), g(rng), g(rng));
  return v.normalized();
}

VmfComponent lobe(double alpha, double kappa, const Vec3& mu) {
  VmfComponent c;
  c.alpha = alpha, c.kappa = kappa, c.mu = mu.normalized(), c.r = vmf_mean_length(kappa) * c.mu;
  return c;
}

void expect_matches_brute_force(const std::vector<WeightedNormal>& normals, const std::vector<VmfComponent>& mixture,
                                const char* what) {
  const BruteSums b = brute_e_step(normals, mixture);
  const EStepSums s = vmf_e_step(normals, lobe_terms(mixture));
  // Every term of the sums is within a few ulp; the tolerance allows for the terms dropped below e^-40, the long
  // summations, and the E-step's log(alpha C) - kappa + kappa mu.n, which rounds at the scale of kappa (the
  // brute force's kappa (mu.n - 1) does not).
  double kappa = 0.0;
  for (const VmfComponent& c : mixture) kappa = std::max(kappa, c.kappa);
  EXPECT_NEAR(s.log_likelihood, double(b.log_likelihood),
              1e-12 * std::max(1.0, std::abs(double(b.log_likelihood))) + 1e-15 * kappa)
      << what;
  for (size_t j = 0; j < mixture.size(); ++j) {
    EXPECT_NEAR(s.mass[j], double(b.mass[j]), 1e-13) << what << " lobe " << j;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(s.moment[j][a], b.moment[j][a], 1e-13) << what << " lobe " << j;
  }
}

std::vector<WeightedNormal> equal_weights(std::vector<Vec3> ns) {
  std::vector<WeightedNormal> out;
  for (const Vec3& n : ns) out.push_back({n, 1.0 / double(ns.size())});
  return out;
}

TEST(VmfEStep, MatchesBruteForceOnTheHardCases) {
  const Vec3 z = Vec3::UnitZ(), x = Vec3::UnitX();
  // Identical normals, a lobe at the kappa cap on them and one elsewhere.
  expect_matches_brute_force(equal_weights({z, z, z, z, z}), {lobe(0.5, kVmfKappaMax, z), lobe(0.5, 30, x)},
                             "identical at the cap");
  // Antipodal normals, lobes at the cap on each (the other's term is e^-2e6: dropped, never overflowing).
  expect_matches_brute_force(equal_weights({z, -z, z}), {lobe(0.6, kVmfKappaMax, z), lobe(0.4, kVmfKappaMax, -z)},
                             "antipodal");
  // One normal, one lobe far from it (its only term is the largest: responsibility 1).
  expect_matches_brute_force(equal_weights({x}), {lobe(1.0, kVmfKappaMax, z)}, "one normal");
  // Empty lobes between live ones, and a uniform lobe (kappa 0).
  expect_matches_brute_force(equal_weights({x, z, -x, Vec3(0, 1, 0)}),
                             {VmfComponent{}, lobe(0.3, 0.0, z), VmfComponent{}, lobe(0.7, 5, x)}, "empty lobes");
}

TEST(VmfEStep, MatchesBruteForceOnRandomMixturesOfEveryCount) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (size_t count :
       {size_t(1), size_t(2), size_t(3), size_t(5), size_t(7), size_t(64), size_t(1001), kVmfSumChunk + 3}) {
    std::vector<WeightedNormal> normals;
    double total = 0.0;
    for (size_t i = 0; i < count; ++i) {
      normals.push_back({random_unit(rng), 0.1 + u(rng)});
      total += normals.back().w;
    }
    for (WeightedNormal& n : normals) n.w /= total;
    for (int J : {1, 4, kVmfMaxLobes}) {
      std::vector<VmfComponent> mixture;
      for (int j = 0; j < J; ++j) mixture.push_back(lobe(1.0 / J, std::pow(10.0, 6 * u(rng)), random_unit(rng)));
      expect_matches_brute_force(normals, mixture, ("count " + std::to_string(count)).c_str());
    }
  }
}

TEST(VmfEStep, InstructionPathsAreBitIdentical) {
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "no AVX2 on this processor";
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (size_t count : {size_t(1), size_t(6), size_t(4099)}) {
    std::vector<WeightedNormal> normals;
    for (size_t i = 0; i < count; ++i) normals.push_back({random_unit(rng), 1.0 / double(count)});
    std::vector<VmfComponent> mixture;
    for (int j = 0; j < 5; ++j) mixture.push_back(lobe(0.2, std::pow(10.0, 6 * u(rng)), random_unit(rng)));
    const LobeTerms t = lobe_terms(mixture);
    const EStepSums a = vmf_e_step(normals, t, VmfVectorPath::sse2), b = vmf_e_step(normals, t, VmfVectorPath::avx2);
    EXPECT_EQ(a.log_likelihood, b.log_likelihood);
    for (int j = 0; j < 5; ++j) {
      EXPECT_EQ(a.mass[j], b.mass[j]);
      for (int c = 0; c < 3; ++c) EXPECT_EQ(a.moment[j][c], b.moment[j][c]);
    }
  }
}

// The documented order, one normal at a time: normal i adds to lane i mod 4, each lane's sums in normal order,
// the lanes added in lane order; terms 40 nats below the largest are 0, exp's argument floored at -64.
EStepSums scalar_e_step(const std::vector<WeightedNormal>& normals, const LobeTerms& t) {
  constexpr size_t kLanes = 4;
  double ll[kLanes] = {}, mass[kLanes][kVmfMaxLobes] = {}, moment[kLanes][kVmfMaxLobes][3] = {};
  for (size_t i = 0; i < normals.size(); ++i) {
    const Vec3& n = normals[i].n;
    const size_t lane = i % kLanes;
    double s[kVmfMaxLobes], top = 0.0, sum = 0.0;
    for (size_t l = 0; l < t.count; ++l) {
      s[l] = t.log_scale[l] + t.kappa_mu[0][l] * n[0] + t.kappa_mu[1][l] * n[1] + t.kappa_mu[2][l] * n[2];
      top = l == 0 ? s[l] : std::max(s[l], top);
    }
    for (size_t l = 0; l < t.count; ++l) {
      const double d = s[l] - top;
      s[l] = d < -40.0 ? 0.0 : fast_exp(std::max(d, -64.0));
      sum += s[l];
    }
    ll[lane] += normals[i].w * (top + fast_log(sum));
    const double q = normals[i].w / sum;
    for (size_t l = 0; l < t.count; ++l) {
      mass[lane][l] += s[l] * q;
      for (int a = 0; a < 3; ++a) moment[lane][l][a] += s[l] * q * n[a];
    }
  }
  EStepSums out;
  for (size_t lane = 0; lane < kLanes; ++lane) {
    out.log_likelihood += ll[lane];
    for (size_t l = 0; l < t.count; ++l) {
      out.mass[t.live[l]] += mass[lane][l];
      for (int a = 0; a < 3; ++a) out.moment[t.live[l]][a] += moment[lane][l][a];
    }
  }
  return out;
}

TEST(VmfEStep, SumsAreThoseOfTheDocumentedOrderBitForBit) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (size_t count = 1; count <= 70; count += (count < 40 ? 1 : 13)) {
    for (int J : {1, 3, 4, 9}) {
      // Lobes from broad to the cap, so that blocks mix negligible and live terms.
      std::vector<VmfComponent> mixture;
      for (int j = 0; j < J; ++j)
        mixture.push_back(lobe(u(rng) + 0.05, j == 0 ? kVmfKappaMax : std::pow(10.0, 6 * u(rng)), random_unit(rng)));
      std::vector<WeightedNormal> normals;
      for (size_t i = 0; i < count; ++i)
        normals.push_back({i % 3 == 0 ? mixture[0].mu : random_unit(rng), u(rng) / double(count)});
      const LobeTerms t = lobe_terms(mixture);
      const EStepSums expected = scalar_e_step(normals, t);
      for (VmfVectorPath path : {VmfVectorPath::sse2, VmfVectorPath::avx2}) {
        if (path == VmfVectorPath::avx2 && !__builtin_cpu_supports("avx2")) continue;
        const EStepSums s = vmf_e_step(normals, t, path);
        const std::string what = "count " + std::to_string(count) + ", " + std::to_string(J) + " lobes";
        EXPECT_EQ(s.log_likelihood, expected.log_likelihood) << what;
        for (int j = 0; j < J; ++j) {
          EXPECT_EQ(s.mass[j], expected.mass[j]) << what << " lobe " << j;
          for (int a = 0; a < 3; ++a) EXPECT_EQ(s.moment[j][a], expected.moment[j][a]) << what << " lobe " << j;
        }
      }
    }
  }
}

}  // namespace
}  // namespace mbk
