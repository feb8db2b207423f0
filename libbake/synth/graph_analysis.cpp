// Exemplar-graph analysis (see graph_analysis.h).
#include "libbake/synth/graph_analysis.h"

#include <algorithm>

#include "libbake/core/parallel.h"
#include "libbake/synth/loop_transitions.h"
#include "libbake/synth/neighbourhood_pca.h"
#include "libbake/synth/neighbourhood_search.h"

namespace mbk {
namespace {

constexpr uint32_t kNearestConsidered = 64;  // neighbours among which the dispersed candidates are chosen

uint32_t torus_distance(uint32_t a, uint32_t b, uint32_t m) {
  const uint32_t d = a > b ? a - b : b - a;
  return std::min(d, m - d);
}

}  // namespace

void stack_neighbourhood(const Image& level, uint32_t h, uint32_t x, uint32_t y, float* out) {
  const int64_t m = level.width, r = kSynthNeighbourhood / 2;
  for (int64_t dy = -r; dy <= r; ++dy)
    for (int64_t dx = -r; dx <= r; ++dx) {
      const uint32_t sx = uint32_t(((int64_t(x) + dx * h) % m + m) % m);
      const uint32_t sy = uint32_t(((int64_t(y) + dy * h) % m + m) % m);
      for (uint32_t c = 0; c < level.channels; ++c) *out++ = level.at(sx, sy, c);
    }
}

GraphAnalysis analyse_graph(const ExemplarGraph& graph, const std::vector<Image>& exemplars,
                            const GraphAnalysisOptions& options, Progress& progress) {
  GraphAnalysis a;
  a.side = exemplars.at(0).width;
  a.channels = exemplars[0].channels;
  a.K = options.candidates;
  const uint32_t m = a.side, ch = a.channels, dims = kSynthNeighbourhood * kSynthNeighbourhood * ch;
  const size_t texels = size_t(m) * m;
  for (const Image& e : exemplars) a.stacks.push_back(build_gaussian_stack(e));
  a.levels = a.stacks[0].levels;
  a.admissible = admissible_levels(uint32_t(graph.exemplars.size()), graph.edges, a.levels);
  const uint32_t E = uint32_t(exemplars.size());
  a.candidates.assign(size_t(E) * a.levels * texels * a.K, SynthCandidate{});
  a.transfer.assign(a.candidates.size() * ch, 0.0f);
  a.kept_variance.assign(size_t(E) * a.levels, 1.0);

  // Every level's neighbourhood vectors, once.
  std::vector<std::vector<float>> vectors(size_t(E) * a.levels);
  parallel_for(0, int64_t(vectors.size()), [&](int64_t s) {
    const uint32_t i = uint32_t(s / a.levels), k = uint32_t(s % a.levels);
    std::vector<float>& v = vectors[size_t(s)];
    v.resize(texels * dims);
    for (uint32_t y = 0; y < m; ++y)
      for (uint32_t x = 0; x < m; ++x)
        stack_neighbourhood(a.stacks[i].images[k], a.stacks[i].spacing(k), x, y, &v[(size_t(y) * m + x) * dims]);
  });

  std::vector<double> contrast(size_t(E) * a.levels);
  for (uint32_t i = 0; i < E; ++i)
    for (uint32_t k = 0; k < a.levels; ++k)
      contrast[size_t(i) * a.levels + k] =
          neighbourhood_contrast(a.stacks[i].images[k].pixels.data(), m, ch, a.stacks[i].spacing(k));
  const LoopContrast loops(a.levels, std::move(contrast));

  progress.start("analysis", uint64_t(E) * a.levels);
  for (uint32_t i = 0; i < E; ++i)
    for (uint32_t k = 0; k < a.levels; ++k) {
      std::vector<StackLevel> pool_levels;  // the admissible levels correction may move to (loop_transitions.h)
      for (const StackLevel& l : a.admissible[i][k])
        if (loop_transition_allowed(i, k, l.exemplar, l.level, a.levels - 1)) pool_levels.push_back(l);
      if (pool_levels.empty()) {
        progress.advance();
        continue;
      }
      std::vector<float> pool;
      for (const StackLevel& l : pool_levels) {  // loop levels at the source's contrast (loop_transitions.h)
        const std::vector<float>& v = vectors[size_t(l.exemplar) * a.levels + l.level];
        const size_t start = pool.size();
        pool.insert(pool.end(), v.begin(), v.end());
        const double target = loops.target(i, k, l.exemplar, l.level);
        if (target > 0.0)
          for (size_t n = start; n < pool.size(); n += dims) bring_to_contrast(&pool[n], ch, target);
      }
      const std::vector<float>& source = vectors[size_t(i) * a.levels + k];
      // Where a loop is searched, every match carries its transfer (loop_transitions.h): ranked by the error left
      // after the best constant offset, i.e. between mean-removed neighbourhoods.
      std::vector<float> query = source;
      if (std::any_of(pool_levels.begin(), pool_levels.end(),
                      [&](const StackLevel& l) { return loops.target(i, k, l.exemplar, l.level) > 0.0; })) {
        for (size_t n = 0; n < pool.size(); n += dims) remove_neighbourhood_mean(&pool[n], ch);
        for (size_t n = 0; n < query.size(); n += dims) remove_neighbourhood_mean(&query[n], ch);
      }
      const NeighbourhoodPca pca = fit_pca(pool, dims, options.pca_components);
      a.kept_variance[size_t(i) * a.levels + k] = pca.kept_variance;
      const uint32_t comps = uint32_t(pca.basis.cols());
      const std::vector<uint32_t> nearest =
          nearest_neighbours(pca.project(pool), pca.project(query), comps, kNearestConsidered);
      const uint32_t found = uint32_t(nearest.size() / texels);
      parallel_for(0, int64_t(texels), [&](int64_t t) {
        const size_t base = a.candidate_index(i, k, 0, 0) + size_t(t) * a.K;
        // Candidate 0 is the nearest; each later one the nearest that is dispersed from the earlier ones, or,
        // when none of the considered neighbours is (a smooth coarse level, where the nearest neighbourhoods all
        // lie around the texel), the considered one farthest from them.
        const auto spread_from_chosen = [&](uint32_t chosen, const StackLevel& l, uint32_t x, uint32_t y) {
          uint32_t nearest_chosen = UINT32_MAX;
          for (uint32_t c = 0; c < chosen; ++c) {
            const SynthCandidate& q = a.candidates[base + c];
            if (q.exemplar == l.exemplar && q.level == l.level)
              nearest_chosen = std::min(nearest_chosen, std::max(torus_distance(q.x, x, m), torus_distance(q.y, y, m)));
          }
          return nearest_chosen;
        };
        for (uint32_t chosen = 0; chosen < std::min(a.K, found); ++chosen) {
          uint32_t pick = found, fallback = found, fallback_spread = 0;
          for (uint32_t n = 0; n < found && pick == found; ++n) {
            const uint32_t p = nearest[size_t(t) * found + n];
            const StackLevel& l = pool_levels[p / texels];
            const uint32_t x = (p % texels) % m, y = uint32_t((p % texels) / m);
            const uint32_t spread = spread_from_chosen(chosen, l, x, y);
            if (spread >= std::max(2u, std::min(a.stacks[l.exemplar].spacing(l.level), m / 4)))
              pick = n;
            else if (spread > fallback_spread)
              fallback = n, fallback_spread = spread;
          }
          if (pick == found) pick = fallback;
          if (pick == found) break;  // every considered texel is already a candidate
          const uint32_t p = nearest[size_t(t) * found + pick];
          const StackLevel& l = pool_levels[p / texels];
          const uint32_t x = (p % texels) % m, y = uint32_t((p % texels) / m);
          a.candidates[base + chosen] = {l.exemplar, l.level, x, y};
          if (l.exemplar != i || l.level < k) {  // Sec. 5.3: b = mean(source - destination); loops too
            const float* s = &source[size_t(t) * dims];
            const float* d = &vectors[size_t(l.exemplar) * a.levels + l.level][(size_t(y) * m + x) * dims];
            for (uint32_t c = 0; c < ch; ++c) {
              double sum = 0.0;
              for (uint32_t j = 0; j < kSynthNeighbourhood * kSynthNeighbourhood; ++j)
                sum += double(s[j * ch + c]) - d[j * ch + c];
              a.transfer[(base + chosen) * ch + c] = float(sum / (kSynthNeighbourhood * kSynthNeighbourhood));
            }
          }
        }
      });
      progress.advance();
    }
  // Sec. 5.4: one PCA per synthesis level, over the neighbourhoods of every stack level of its red depth.
  a.superexemplar = superexemplar_levels(E, graph.edges, a.levels, graph.root);
  for (const std::vector<StackLevel>& set : a.superexemplar.sets) {
    std::vector<float> all;
    for (const StackLevel& l : set) {
      const std::vector<float>& v = vectors[size_t(l.exemplar) * a.levels + l.level];
      all.insert(all.end(), v.begin(), v.end());
    }
    a.synthesis_pca.push_back(fit_pca(all, dims, kSynthesisPcaComponents));
  }
  progress.finish();
  return a;
}

}  // namespace mbk
