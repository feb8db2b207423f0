// Gaussian stacks and the analysis of exemplar graphs ([Han08] thesis Secs. 5.2.1, 5.2.2.3, 5.3;
// libbake/synth/gaussian_stack.h, graph_analysis.h): stack levels against the closed-form attenuation of a periodic
// Gaussian; candidate sets against brute-force nearest neighbours in the same PCA space, dispersed, admissible, and
// transfer functions against their definition.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include "libbake/core/parallel.h"
#include "libbake/synth/graph_analysis.h"
#include "libbake/synth/loop_transitions.h"
#include "libbake/synth/neighbourhood_pca.h"

namespace mbk {
namespace {

Image noise_image(uint32_t m, uint32_t channels, uint64_t seed, float offset = 0.0f) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Image im{m, m, channels, {}};
  for (size_t i = 0; i < size_t(m) * m * channels; ++i) im.pixels.push_back(u(rng) + offset);
  return im;
}

// A cosine of f periods across the exemplar keeps exp(-2 pi^2 sigma^2 (f / m)^2) of its amplitude in a level of
// standard deviation sigma (the Gaussian's Fourier transform; the sampled, folded kernel differs from it by
// ~exp(-2 pi^2 sigma^2), negligible for sigma >= 2).
TEST(GaussianStack, LevelsAttenuateACosineAsTheGaussianSays) {
  const uint32_t m = 64, f = 3;
  Image im{m, m, 1, {}};
  for (uint32_t row = 0; row < m; ++row)
    for (uint32_t x = 0; x < m; ++x) im.pixels.push_back(float(std::cos(2 * std::numbers::pi * f * x / m)));
  const GaussianStack s = build_gaussian_stack(im);
  ASSERT_EQ(s.levels, 7u);
  EXPECT_EQ(s.images[6].pixels, im.pixels);  // the finest level is the exemplar
  EXPECT_EQ(s.spacing(6), 1u);
  EXPECT_EQ(s.spacing(0), 64u);
  for (uint32_t k = 0; k + 2 < s.levels; ++k) {  // sigma = 2^(L-k-1) >= 2
    const double sigma = std::ldexp(1.0, int(s.levels) - 2 - int(k));
    const double expected = std::exp(-2 * std::numbers::pi * std::numbers::pi * sigma * sigma * f * f / (m * m));
    for (uint32_t x = 0; x < m; ++x)
      EXPECT_NEAR(s.images[k].at(x, 17, 0), expected * std::cos(2 * std::numbers::pi * f * x / m), 1e-6) << k;
  }
}

// Level 0 (sigma = m / 2) keeps at most exp(-pi^2 / 2) ~ 0.7% of any non-constant Fourier mode, so its deviation
// from the mean is at most that fraction of the exemplar's (Parseval), and its mean is the exemplar's.
TEST(GaussianStack, CoarsestLevelIsNearlyTheMean) {
  const Image im = noise_image(32, 3, 4);
  const GaussianStack s = build_gaussian_stack(im);
  for (uint32_t c = 0; c < 3; ++c) {
    double mean = 0.0, mean0 = 0.0;
    for (size_t i = 0; i < 32 * 32; ++i) mean += im.pixels[i * 3 + c], mean0 += s.images[0].pixels[i * 3 + c];
    mean /= 32 * 32;
    mean0 /= 32 * 32;
    EXPECT_NEAR(mean0, mean, 1e-6);
    double var = 0.0, var0 = 0.0;
    for (size_t i = 0; i < 32 * 32; ++i) {
      var += std::pow(im.pixels[i * 3 + c] - mean, 2);
      var0 += std::pow(s.images[0].pixels[i * 3 + c] - mean0, 2);
    }
    EXPECT_LE(std::sqrt(var0), std::exp(-std::numbers::pi * std::numbers::pi / 2) * std::sqrt(var) + 1e-7);
    EXPECT_GT(var0, 0.0);  // not a flat mean: the folded Gaussian is exact, not a box
  }
}

// Two exemplars: A -> B (r = 1), B -> B (r = 1, an infinite zoom); B is A's colours shifted by +0.2 (an
// inconsistent graph, Sec. 4.2).
struct TwoExemplarGraph {
  ExemplarGraph graph;
  std::vector<Image> images;
  TwoExemplarGraph(uint32_t m) {
    graph.exemplars = {{"A", "a.png", "a.png"}, {"B", "b.png", "b.png"}};
    graph.root = 0;
    graph.edges = {{0, 1, 1}, {1, 1, 1}};
    images = {noise_image(m, 3, 1), noise_image(m, 3, 2, 0.2f)};
  }
};

double squared_distance(const std::vector<float>& a, const std::vector<float>& b, size_t i, size_t j, uint32_t d) {
  double s = 0.0;
  for (uint32_t k = 0; k < d; ++k) s += double(a[i * d + k] - b[j * d + k]) * (a[i * d + k] - b[j * d + k]);
  return s;
}

// The mean 5 x 5 neighbourhood variance of a level: 0 when constant; for a checkerboard of +-1 at spacing 1 every
// neighbourhood holds 13 of one sign and 12 of the other (variance 1 - 1/625), at spacing 2 one colour (0).
TEST(LoopTransitions, NeighbourhoodContrastOfConstantAndCheckerboard) {
  const uint32_t m = 8;
  std::vector<float> flat(m * m, 0.25f), board(m * m);
  for (uint32_t y = 0; y < m; ++y)
    for (uint32_t x = 0; x < m; ++x) board[y * m + x] = (x + y) % 2 ? 1.0f : -1.0f;
  EXPECT_EQ(neighbourhood_contrast(flat.data(), m, 1, 1), 0.0);
  EXPECT_NEAR(neighbourhood_contrast(board.data(), m, 1, 1), 1.0 - 1.0 / 625.0, 1e-12);
  EXPECT_EQ(neighbourhood_contrast(board.data(), m, 1, 2), 0.0);
  // bring_to_contrast keeps a neighbourhood's mean and scales its deviations to the target variance: 0..24 has
  // variance 52, so target 13 halves them; a constant neighbourhood stays.
  std::vector<float> v(25), flat25(25, 0.5f);
  for (uint32_t j = 0; j < 25; ++j) v[j] = float(j);
  bring_to_contrast(v.data(), 1, 13.0);
  for (uint32_t j = 0; j < 25; ++j) EXPECT_NEAR(v[j], 12.0 + 0.5 * (double(j) - 12.0), 1e-5);
  bring_to_contrast(flat25.data(), 1, 13.0);
  for (float f : flat25) EXPECT_EQ(f, 0.5f);
  // Loops below the finest level are refused, other transitions kept.
  EXPECT_FALSE(loop_transition_allowed(0, 3, 0, 2, 6));
  EXPECT_TRUE(loop_transition_allowed(0, 6, 0, 5, 6));
  EXPECT_TRUE(loop_transition_allowed(0, 3, 0, 3, 6));
  EXPECT_TRUE(loop_transition_allowed(0, 3, 1, 1, 6));
}

TEST(GraphAnalysis, FirstCandidateIsTheBruteForceNearestInPcaSpaceAndOthersAdmissibleDistinctAndMostlyDispersed) {
  const uint32_t m = 16;
  TwoExemplarGraph g(m);
  GraphAnalysisOptions options;
  const GraphAnalysis a = analyse_graph(g.graph, g.images, options, Progress::silent());
  ASSERT_EQ(a.levels, 5u);
  const uint32_t ch = 3, dims = 25 * ch;
  size_t checked = 0, same_level = 0, dispersed = 0, second_checked = 0;
  for (uint32_t i = 0; i < 2; ++i)
    for (uint32_t k = 0; k < a.levels; ++k) {
      std::vector<StackLevel> pool_levels;  // loops only from the finest level (loop_transitions.h)
      for (const StackLevel& l : a.admissible[i][k])
        if (loop_transition_allowed(i, k, l.exemplar, l.level, a.levels - 1)) pool_levels.push_back(l);
      if (pool_levels.empty()) {
        EXPECT_EQ(a.candidates[a.candidate_index(i, k, 0, 0)].exemplar, kNoCandidate);
        continue;
      }
      // The same PCA space, then every pool texel by brute force.
      std::vector<float> pool, source(size_t(m) * m * dims);
      for (const StackLevel& l : pool_levels)
        for (uint32_t y = 0; y < m; ++y)
          for (uint32_t x = 0; x < m; ++x) {
            std::vector<float> v(dims);
            stack_neighbourhood(a.stacks[l.exemplar].images[l.level], a.stacks[l.exemplar].spacing(l.level), x, y,
                                v.data());
            if (l.exemplar == i && l.level < k)  // a loop: at the source level's contrast
              bring_to_contrast(
                  v.data(), ch,
                  neighbourhood_contrast(a.stacks[i].images[k].pixels.data(), m, ch, a.stacks[i].spacing(k)));
            pool.insert(pool.end(), v.begin(), v.end());
          }
      for (uint32_t y = 0; y < m; ++y)
        for (uint32_t x = 0; x < m; ++x)
          stack_neighbourhood(a.stacks[i].images[k], a.stacks[i].spacing(k), x, y, &source[(size_t(y) * m + x) * dims]);
      // With a loop in the pool, every vector mean-removed (matches ranked after their transfers).
      bool loop = false;
      for (const StackLevel& l : pool_levels) loop = loop || (l.exemplar == i && l.level < k);
      if (loop) {
        for (size_t n = 0; n < pool.size(); n += dims) remove_neighbourhood_mean(&pool[n], ch);
        for (size_t n = 0; n < source.size(); n += dims) remove_neighbourhood_mean(&source[n], ch);
      }
      const NeighbourhoodPca pca = fit_pca(pool, dims, options.pca_components);
      const std::vector<float> p = pca.project(pool), q = pca.project(source);
      const uint32_t comps = uint32_t(pca.basis.cols());
      const uint32_t L = a.levels - 1;
      const bool own_level_in_pool =
          std::find(pool_levels.begin(), pool_levels.end(), StackLevel{i, k}) != pool_levels.end();
      for (uint32_t t = 0; t < m * m; ++t) {
        double best = INFINITY;
        for (size_t j = 0; j < p.size() / comps; ++j) best = std::min(best, squared_distance(q, p, t, j, comps));
        // Where the texel's own level is searched the nearest is the texel itself (distance 0): the second
        // candidate is the informative one. By brute force: the 64 nearest, the first dispersed one.
        if (own_level_in_pool || k == L) {
          std::vector<std::pair<double, size_t>> ranked;
          for (size_t j = 0; j < p.size() / comps; ++j) ranked.push_back({squared_distance(q, p, t, j, comps), j});
          std::sort(ranked.begin(), ranked.end());
          const SynthCandidate& c0 = a.candidates[a.candidate_index(i, k, t % m, t / m)];
          const SynthCandidate& c1 = a.candidates[a.candidate_index(i, k, t % m, t / m) + 1];
          const auto torus = [&](uint32_t u, uint32_t v) { return std::min((u + m - v) % m, (v + m - u) % m); };
          double expected = -1.0;
          for (size_t r = 0; r < std::min<size_t>(64, ranked.size()) && expected < 0; ++r) {
            const size_t j = ranked[r].second;
            const StackLevel& l = pool_levels[j / (m * m)];
            const uint32_t x = uint32_t(j % (m * m)) % m, y = uint32_t(j % (m * m)) / m;
            const bool same_level = l.exemplar == c0.exemplar && l.level == c0.level;
            const uint32_t spread = std::max(2u, std::min(a.stacks[l.exemplar].spacing(l.level), m / 4));
            if (!same_level || std::max(torus(x, c0.x), torus(y, c0.y)) >= spread) expected = ranked[r].first;
          }
          size_t at1 = 0;
          while (!(pool_levels[at1].exemplar == c1.exemplar && pool_levels[at1].level == c1.level)) ++at1;
          const double got1 = squared_distance(q, p, t, at1 * m * m + size_t(c1.y) * m + c1.x, comps);
          if (expected >= 0) {
            EXPECT_NEAR(got1, expected, 1e-4 * std::max(1.0, expected)) << "exemplar " << i << " level " << k;
            ++second_checked;
          }
        }
        const SynthCandidate& c = a.candidates[a.candidate_index(i, k, t % m, t / m)];
        ASSERT_NE(c.exemplar, kNoCandidate);
        size_t at = 0;
        while (!(pool_levels[at].exemplar == c.exemplar && pool_levels[at].level == c.level)) ++at;
        const double got = squared_distance(q, p, t, at * m * m + size_t(c.y) * m + c.x, comps);
        EXPECT_NEAR(got, best, 1e-4 * std::max(1.0, best));
        ++checked;
        // Every candidate admissible; the second far enough from the first when both share a level.
        for (uint32_t n = 0; n < a.K; ++n) {
          const SynthCandidate& cn = a.candidates[a.candidate_index(i, k, t % m, t / m) + n];
          if (cn.exemplar == kNoCandidate) continue;
          EXPECT_NE(std::find(pool_levels.begin(), pool_levels.end(), StackLevel{cn.exemplar, cn.level}),
                    pool_levels.end());
        }
        // The second differs from the first, and is dispersed from it unless no near match was (counted).
        const SynthCandidate& c1 = a.candidates[a.candidate_index(i, k, t % m, t / m) + 1];
        ASSERT_NE(c1.exemplar, kNoCandidate);
        EXPECT_FALSE(c1.exemplar == c.exemplar && c1.level == c.level && c1.x == c.x && c1.y == c.y);
        if (c1.exemplar == c.exemplar && c1.level == c.level) {
          const auto torus = [&](uint32_t u, uint32_t v) { return std::min((u + m - v) % m, (v + m - u) % m); };
          ++same_level;
          dispersed += std::max(torus(c.x, c1.x), torus(c.y, c1.y)) >=
                       std::max(2u, std::min(a.stacks[c.exemplar].spacing(c.level), m / 4));
        }
      }
    }
  EXPECT_GT(checked, 2000u);
  EXPECT_GT(second_checked, 1000u);
  std::cout << dispersed << " of " << same_level << " second candidates in the first's level are dispersed\n";
  EXPECT_GT(dispersed, same_level * 3 / 4);
}

TEST(GraphAnalysis, TransferFunctionsAreTheMeanNeighbourhoodDifference_ZeroWithinAnExemplar) {
  const uint32_t m = 16;
  TwoExemplarGraph g(m);
  const GraphAnalysis a = analyse_graph(g.graph, g.images, {}, Progress::silent());
  size_t across = 0;
  std::vector<float> s(75), d(75);
  for (uint32_t i = 0; i < 2; ++i)
    for (uint32_t k = 0; k < a.levels; ++k)
      for (uint32_t y = 0; y < m; ++y)
        for (uint32_t x = 0; x < m; ++x)
          for (uint32_t n = 0; n < a.K; ++n) {
            const size_t at = a.candidate_index(i, k, x, y) + n;
            const SynthCandidate& c = a.candidates[at];
            if (c.exemplar == kNoCandidate) continue;
            stack_neighbourhood(a.stacks[i].images[k], a.stacks[i].spacing(k), x, y, s.data());
            stack_neighbourhood(a.stacks[c.exemplar].images[c.level], a.stacks[c.exemplar].spacing(c.level), c.x, c.y,
                                d.data());
            for (uint32_t ch = 0; ch < 3; ++ch) {
              double b = 0.0;
              for (uint32_t j = 0; j < 25; ++j) b += (s[j * 3 + ch] - d[j * 3 + ch]) / 25.0;
              if (c.exemplar == i && c.level >= k) {  // within a level: none; across a loop as across exemplars
                EXPECT_EQ(a.transfer[at * 3 + ch], 0.0f);
              } else {
                EXPECT_NEAR(a.transfer[at * 3 + ch], b, 1e-6);
              }
            }
            across += c.exemplar != i;
          }
  // A's levels k >= 1 look into B, whose colours are 0.2 brighter: those transfers pull them back down.
  EXPECT_GT(across, 100u);
}

// Sec. 5.4: one PCA per synthesis level over the neighbourhoods of its red depth's stack levels: the mean is theirs,
// the basis orthonormal, and the first component holds more variance than any of 200 random directions.
TEST(GraphAnalysis, SynthesisLevelPcaSpansItsRedDepthsNeighbourhoods) {
  const uint32_t m = 16;
  TwoExemplarGraph g(m);
  const GraphAnalysis a = analyse_graph(g.graph, g.images, {}, Progress::silent());
  ASSERT_EQ(a.synthesis_pca.size(), a.superexemplar.sets.size());
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss;
  for (size_t d = 0; d < a.synthesis_pca.size(); ++d) {
    std::vector<Eigen::VectorXd> v;
    for (const StackLevel& l : a.superexemplar.sets[d])
      for (uint32_t y = 0; y < m; ++y)
        for (uint32_t x = 0; x < m; ++x) {
          std::vector<float> n(75);
          stack_neighbourhood(a.stacks[l.exemplar].images[l.level], a.stacks[l.exemplar].spacing(l.level), x, y,
                              n.data());
          v.push_back(Eigen::Map<Eigen::VectorXf>(n.data(), 75).cast<double>());
        }
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(75);
    for (const auto& x : v) mean += x / double(v.size());
    const NeighbourhoodPca& pca = a.synthesis_pca[d];
    EXPECT_LT((pca.mean - mean).norm(), 1e-5) << d;
    ASSERT_EQ(pca.basis.cols(), Eigen::Index(kSynthesisPcaComponents));
    EXPECT_LT((pca.basis.transpose() * pca.basis - Eigen::MatrixXd::Identity(6, 6)).norm(), 1e-9) << d;
    const auto variance_along = [&](const Eigen::VectorXd& dir) {
      double s = 0.0;
      for (const auto& x : v) s += std::pow((x - mean).dot(dir), 2);
      return s / double(v.size());
    };
    const double first = variance_along(pca.basis.col(0));
    for (int r = 0; r < 200; ++r) {
      Eigen::VectorXd dir(75);
      for (int i = 0; i < 75; ++i) dir[i] = gauss(rng);
      EXPECT_LE(variance_along(dir.normalized()), first * (1 + 1e-9)) << d;
    }
  }
}

TEST(GraphAnalysis, SameCandidatesWhateverTheThreadCount) {
  TwoExemplarGraph g(16);
  const GraphAnalysis a = analyse_graph(g.graph, g.images, {}, Progress::silent());
  const int threads = thread_count();
  set_thread_count(1);
  const GraphAnalysis b = analyse_graph(g.graph, g.images, {}, Progress::silent());
  set_thread_count(threads);
  ASSERT_EQ(a.candidates.size(), b.candidates.size());
  for (size_t i = 0; i < a.candidates.size(); ++i) {
    EXPECT_EQ(a.candidates[i].exemplar, b.candidates[i].exemplar);
    EXPECT_EQ(a.candidates[i].x, b.candidates[i].x);
    EXPECT_EQ(a.candidates[i].y, b.candidates[i].y);
  }
  EXPECT_EQ(a.transfer, b.transfer);
}

}  // namespace
}  // namespace mbk
