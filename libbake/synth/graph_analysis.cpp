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

namespace {

// Every stack level's neighbourhood vectors, [exemplar * levels + level], each texels x dims floats.
std::vector<std::vector<float>> level_neighbourhood_vectors(const GraphAnalysis& a) {
  const uint32_t m = a.side, dims = kSynthNeighbourhood * kSynthNeighbourhood * a.channels;
  std::vector<std::vector<float>> vectors(a.stacks.size() * a.levels);
  parallel_for(0, int64_t(vectors.size()), [&](int64_t s) {
    const uint32_t i = uint32_t(s / a.levels), k = uint32_t(s % a.levels);
    std::vector<float>& v = vectors[size_t(s)];
    v.resize(size_t(m) * m * dims);
    for (uint32_t y = 0; y < m; ++y)
      for (uint32_t x = 0; x < m; ++x)
        stack_neighbourhood(a.stacks[i].images[k], a.stacks[i].spacing(k), x, y, &v[(size_t(y) * m + x) * dims]);
  });
  return vectors;
}

LoopContrast stack_level_contrasts(const GraphAnalysis& a) {
  std::vector<double> contrast(a.stacks.size() * a.levels);
  for (size_t i = 0; i < a.stacks.size(); ++i)
    for (uint32_t k = 0; k < a.levels; ++k)
      contrast[i * a.levels + k] =
          neighbourhood_contrast(a.stacks[i].images[k].pixels.data(), a.side, a.channels, a.stacks[i].spacing(k));
  return LoopContrast(a.levels, std::move(contrast));
}

// What stack level (i, k) is matched against: the admissible levels correction may move to (loop_transitions.h),
// their neighbourhoods (loop levels at the source's contrast) and the source's own. Where a loop is searched, every
// match carries its transfer: ranked by the error left after the best constant offset, i.e. between mean-removed
// neighbourhoods.
struct SearchPool {
  std::vector<StackLevel> levels;
  std::vector<float> neighbourhoods, query;
};

SearchPool search_pool(const GraphAnalysis& a, const std::vector<std::vector<float>>& vectors,
                       const LoopContrast& loops, uint32_t i, uint32_t k) {
  const uint32_t ch = a.channels, dims = kSynthNeighbourhood * kSynthNeighbourhood * ch;
  SearchPool pool;
  for (const StackLevel& l : a.admissible[i][k])
    if (loop_transition_allowed(i, k, l.exemplar, l.level, a.levels - 1)) pool.levels.push_back(l);
  if (pool.levels.empty()) return pool;
  for (const StackLevel& l : pool.levels) {
    const std::vector<float>& v = vectors[size_t(l.exemplar) * a.levels + l.level];
    const size_t start = pool.neighbourhoods.size();
    pool.neighbourhoods.insert(pool.neighbourhoods.end(), v.begin(), v.end());
    const double target = loops.target(i, k, l.exemplar, l.level);
    if (target > 0.0)
      for (size_t n = start; n < pool.neighbourhoods.size(); n += dims)
        bring_to_contrast(&pool.neighbourhoods[n], ch, target);
  }
  pool.query = vectors[size_t(i) * a.levels + k];
  if (std::any_of(pool.levels.begin(), pool.levels.end(),
                  [&](const StackLevel& l) { return loops.target(i, k, l.exemplar, l.level) > 0.0; })) {
    for (size_t n = 0; n < pool.neighbourhoods.size(); n += dims)
      remove_neighbourhood_mean(&pool.neighbourhoods[n], ch);
    for (size_t n = 0; n < pool.query.size(); n += dims) remove_neighbourhood_mean(&pool.query[n], ch);
  }
  return pool;
}

// Texel t of level (i, k): up to K candidates from its `found` nearest pool texels (`nearest`, best first).
// Candidate 0 is the nearest; each later one the nearest that is dispersed from the earlier ones, or, when none of
// the considered neighbours is (a smooth coarse level, where the nearest neighbourhoods all lie around the texel),
// the considered one farthest from them. Each candidate that leaves the level gets its transfer b = mean(source -
// destination) (Sec. 5.3; loops too). `source` is the texel's neighbourhood.
void choose_candidates(GraphAnalysis& a, const std::vector<std::vector<float>>& vectors,
                       const std::vector<StackLevel>& pool_levels, const uint32_t* nearest, uint32_t found, uint32_t i,
                       uint32_t k, size_t t, const float* source) {
  const uint32_t m = a.side, ch = a.channels, dims = kSynthNeighbourhood * kSynthNeighbourhood * ch;
  const size_t texels = size_t(m) * m, base = a.candidate_index(i, k, 0, 0) + t * a.K;
  const auto texel_of = [&](uint32_t p, uint32_t& x, uint32_t& y) -> const StackLevel& {
    x = uint32_t((p % texels) % m);
    y = uint32_t((p % texels) / m);
    return pool_levels[p / texels];
  };
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
    uint32_t pick = found, fallback = found, fallback_spread = 0, x, y;
    for (uint32_t n = 0; n < found && pick == found; ++n) {
      const StackLevel& l = texel_of(nearest[n], x, y);
      const uint32_t spread = spread_from_chosen(chosen, l, x, y);
      if (spread >= std::max(2u, std::min(a.stacks[l.exemplar].spacing(l.level), m / 4)))
        pick = n;
      else if (spread > fallback_spread)
        fallback = n, fallback_spread = spread;
    }
    if (pick == found) pick = fallback;
    if (pick == found) break;  // every considered texel is already a candidate
    const StackLevel& l = texel_of(nearest[pick], x, y);
    a.candidates[base + chosen] = {l.exemplar, l.level, x, y};
    if (l.exemplar != i || l.level < k) {
      const float* d = &vectors[size_t(l.exemplar) * a.levels + l.level][(size_t(y) * m + x) * dims];
      for (uint32_t c = 0; c < ch; ++c) {
        double sum = 0.0;
        for (uint32_t j = 0; j < kSynthNeighbourhood * kSynthNeighbourhood; ++j)
          sum += double(source[j * ch + c]) - d[j * ch + c];
        a.transfer[(base + chosen) * ch + c] = float(sum / (kSynthNeighbourhood * kSynthNeighbourhood));
      }
    }
  }
}

}  // namespace

GraphAnalysis analyse_graph(const ExemplarGraph& graph, const std::vector<Image>& exemplars,
                            const GraphAnalysisOptions& options, Progress& progress) {
  GraphAnalysis a;
  a.side = exemplars.at(0).width;
  a.channels = exemplars[0].channels;
  a.K = options.candidates;
  const uint32_t m = a.side, dims = kSynthNeighbourhood * kSynthNeighbourhood * a.channels;
  const size_t texels = size_t(m) * m;
  for (const Image& e : exemplars) a.stacks.push_back(build_gaussian_stack(e));
  a.levels = a.stacks[0].levels;
  a.admissible = admissible_levels(uint32_t(graph.exemplars.size()), graph.edges, a.levels);
  const uint32_t E = uint32_t(exemplars.size());
  a.candidates.assign(size_t(E) * a.levels * texels * a.K, SynthCandidate{});
  a.transfer.assign(a.candidates.size() * a.channels, 0.0f);
  a.kept_variance.assign(size_t(E) * a.levels, 1.0);
  const std::vector<std::vector<float>> vectors = level_neighbourhood_vectors(a);
  const LoopContrast loops = stack_level_contrasts(a);

  progress.start("analysis", uint64_t(E) * a.levels);
  for (uint32_t i = 0; i < E; ++i)
    for (uint32_t k = 0; k < a.levels; ++k) {
      const SearchPool pool = search_pool(a, vectors, loops, i, k);
      if (!pool.levels.empty()) {
        const NeighbourhoodPca pca = fit_pca(pool.neighbourhoods, dims, options.pca_components);
        a.kept_variance[size_t(i) * a.levels + k] = pca.kept_variance;
        const std::vector<uint32_t> nearest = nearest_neighbours(
            pca.project(pool.neighbourhoods), pca.project(pool.query), uint32_t(pca.basis.cols()), kNearestConsidered);
        const uint32_t found = uint32_t(nearest.size() / texels);
        const std::vector<float>& source = vectors[size_t(i) * a.levels + k];
        parallel_for(0, int64_t(texels), [&](int64_t t) {
          choose_candidates(a, vectors, pool.levels, nearest.data() + size_t(t) * found, found, i, k, size_t(t),
                            &source[size_t(t) * dims]);
        });
      }
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
