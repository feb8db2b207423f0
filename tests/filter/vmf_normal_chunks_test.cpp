// Chunks of a texel's normals (libbake/filter/vmf_normal_chunks.h): weight and first moment kept exactly, identical
// normals merged without loss when they fit (checked against a brute-force count), the chunk log-likelihood a
// lower bound of the normals' for any mixture (Jensen: log sum_j exp(a_j + b_j . n) is convex in n) and equal to
// it for exact chunks, heavy atoms kept whole, the lower hemisphere, one normal, the limits of max_chunks.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <tuple>

#include "formats/error.h"
#include "libbake/filter/vmf_normal_chunks.h"
#include "tests/filter/vmf_sampling.h"

namespace mbk {
namespace {

using test::sample_vmf;

// n normals around mu (kappa), quantised to `levels` steps per component when levels > 0 (as 8-bit maps are).
std::vector<WeightedNormal> normals_around(const Vec3& mu, double kappa, size_t n, int levels, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<WeightedNormal> out;
  for (size_t i = 0; i < n; ++i) {
    Vec3 v = sample_vmf(rng, mu, kappa);
    if (levels > 0) v = ((v.array() * levels).round() / levels).matrix().normalized();
    out.push_back({v, 1.0 / double(n)});
  }
  return out;
}

void expect_same_mass_and_moment(const std::vector<WeightedNormal>& normals,
                                 const std::vector<WeightedNormal>& chunks) {
  double w = 0.0, cw = 0.0;
  Vec3 s = Vec3::Zero(), cs = Vec3::Zero();
  for (const auto& x : normals) w += x.w, s += x.w * x.n;
  for (const auto& c : chunks) {
    EXPECT_GT(c.w, 0.0);
    EXPECT_LE(c.n.norm(), 1.0 + 1e-12);
    cw += c.w, cs += c.w * c.n;
  }
  EXPECT_NEAR(cw, w, 1e-12);
  EXPECT_LT((cs - s).norm(), 1e-12);
}

std::vector<VmfComponent> random_mixture(std::mt19937_64& rng, int J) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<VmfComponent> m(static_cast<size_t>(J));
  double total = 0.0;
  for (auto& c : m) {
    c.alpha = 0.1 + u(rng), total += c.alpha;
    c.kappa = std::pow(10.0, 6.0 * u(rng));  // 1 .. 1e6
    c.mu = sample_vmf(rng, Vec3::UnitZ(), 5.0);
  }
  for (auto& c : m) c.alpha /= total;
  return m;
}

TEST(VmfNormalChunks, IdenticalNormalsMergeExactlyWhenTheyFit) {
  const auto normals = normals_around(Vec3(0.2, -0.1, 1.0).normalized(), 200.0, 5000, 40, 1);
  std::map<std::tuple<double, double, double>, double> atoms;  // brute force
  for (const auto& x : normals) atoms[{x.n.x(), x.n.y(), x.n.z()}] += x.w;
  ASSERT_LT(atoms.size(), 1000u);
  const auto chunks = vmf_normal_chunks(normals, atoms.size());
  ASSERT_EQ(chunks.size(), atoms.size());
  for (const auto& c : chunks) {
    const auto found = atoms.find({c.n.x(), c.n.y(), c.n.z()});
    ASSERT_NE(found, atoms.end());  // a normal of the input, bit for bit
    EXPECT_NEAR(c.w, found->second, 1e-15);
  }
  expect_same_mass_and_moment(normals, chunks);
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 20; ++trial) {
    const auto m = random_mixture(rng, 4);
    EXPECT_NEAR(vmf_mixture_log_likelihood(chunks, m), vmf_mixture_log_likelihood(normals, m), 1e-9);
  }
}

TEST(VmfNormalChunks, ChunkLikelihoodIsALowerBound) {
  std::mt19937_64 rng(3);
  for (const size_t max_chunks : {1u, 7u, 64u, 1024u}) {
    const auto normals = normals_around(Vec3(-0.3, 0.4, 0.8).normalized(), 30.0, 20000, 0, max_chunks);
    const auto chunks = vmf_normal_chunks(normals, max_chunks);
    EXPECT_LE(chunks.size(), max_chunks);  // no atoms: every chunk is a cell
    expect_same_mass_and_moment(normals, chunks);
    double gap = 0.0;
    for (int trial = 0; trial < 20; ++trial) {
      const auto m = random_mixture(rng, 1 + trial % 4);
      const double on_chunks = vmf_mixture_log_likelihood(chunks, m),
                   on_normals = vmf_mixture_log_likelihood(normals, m);
      EXPECT_LE(on_chunks, on_normals + 1e-9 + 1e-10 * std::abs(on_normals)) << max_chunks;  // rounding (J = 1: equal)
      gap = std::max(gap, on_normals - on_chunks);
    }
    if (max_chunks == 1) {
      EXPECT_GT(gap, 0.1);  // one chunk: the bound is loose
    }
  }
}

TEST(VmfNormalChunks, HeavyAtomsStayWhole) {
  // 30% of the weight on one exact normal among 10000 distinct ones: with 16 chunks it stays a chunk of its own.
  auto normals = normals_around(Vec3::UnitZ(), 50.0, 10000, 0, 4);
  const Vec3 atom = Vec3(0.1, 0.05, 1.0).normalized();
  for (size_t i = 0; i < 3000; ++i) normals[i].n = atom;
  const auto chunks = vmf_normal_chunks(normals, 16);
  EXPECT_LE(chunks.size(), 2u * 16u);
  size_t found = 0;
  for (const auto& c : chunks)
    if (c.n == atom) {
      ++found;
      EXPECT_NEAR(c.w, 0.3, 1e-12);
    }
  EXPECT_EQ(found, 1u);
  expect_same_mass_and_moment(normals, chunks);
}

TEST(VmfNormalChunks, LowerHemisphereAndLimits) {
  const auto down = normals_around(Vec3(0.1, 0.2, -1.0).normalized(), 100.0, 3000, 0, 5);
  const auto chunks = vmf_normal_chunks(down, 50);
  EXPECT_LE(chunks.size(), 50u);
  EXPECT_GT(chunks.size(), 10u);
  for (const auto& c : chunks) EXPECT_LT(c.n.z(), 0.0);
  expect_same_mass_and_moment(down, chunks);
  const std::vector<WeightedNormal> one = {{Vec3(0.6, 0.0, 0.8), 1.0}};
  const auto single = vmf_normal_chunks(one, 1);
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].n, one[0].n);
  EXPECT_TRUE(vmf_normal_chunks({}, 4).empty());
  EXPECT_THROW(vmf_normal_chunks(one, 0), Error);
}

}  // namespace
}  // namespace mbk
