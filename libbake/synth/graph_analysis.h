// Analysis of an exemplar graph ([Han08] thesis Secs. 5.2.1-5.3): everything parallel synthesis needs, computed
// once per graph.
//   - Gaussian stacks of every exemplar (gaussian_stack.h);
//   - admissible candidate levels of every stack level (admissible_levels.h);
//   - k-coherence candidate sets (Sec. 5.2.2.3, Eq. 5.2, after Tong et al. 2002): for every texel E^i_k[u], the K
//     texels E^j_l[v] over the admissible levels whose 5 x 5 neighbourhoods, sampled at the levels' own spacings
//     h_k and h_l (toroidally), best match its own. Matched in PCA space (neighbourhood_pca.h) by exact FLANN
//     search (neighbourhood_search.h). Deviation [Han08]: Sec. 5.4 matches in one PCA per synthesis level (which
//     we also compute and store, below); the candidate search fits one per source level on its admissible levels,
//     the neighbourhoods it actually compares: a stack level occurs at several red depths through loops and
//     would otherwise need one candidate set per depth (test:
//     GraphAnalysis.FirstCandidateIsTheBruteForceNearestInPcaSpace...);
//     spatially dispersed (after Zelinka & Garland 2002): among the 64 nearest, candidate c > 0 is the best one
//     lying at least max(2, min(h_l, m / 4)) texels (toroidal, per axis max) from every earlier candidate of its
//     level, or, when none does (a smooth coarse level, whose nearest neighbourhoods all lie around the texel), the
//     one farthest from them;
//   - constant-offset transfer functions (Sec. 5.3): per candidate, b = mean over the 25 samples of (source -
//     destination), so that destination + b best matches the source in L2; exactly 0 within one exemplar.
// A level with no admissible level (the finest level of an exemplar without an outgoing edge of r >= 1) has no
// candidates: kNoCandidate; so do slots beyond the number of distinct texels its admissible levels hold.
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/core/progress.h"
#include "formats/admissible_levels.h"
#include "formats/graph_layout.h"
#include "libbake/synth/exemplar_graph.h"
#include "libbake/synth/gaussian_stack.h"
#include "libbake/synth/neighbourhood_pca.h"

namespace mbk {

inline constexpr uint32_t kNoCandidate = kGraphNoCandidate;  // formats/graph_layout.h
inline constexpr uint32_t kSynthNeighbourhood = 5;           // 5 x 5 (Eq. 5.1)
inline constexpr uint32_t kSynthesisPcaComponents = 6;       // the thesis' 6-d PCA space (Sec. 5.4)

struct SynthCandidate {
  uint32_t exemplar = kNoCandidate, level = 0, x = 0, y = 0;
};

struct GraphAnalysisOptions {
  uint32_t candidates = 2;      // K (the thesis: 2)
  uint32_t pca_components = 8;  // of the 25 x channels neighbourhood dimensions
};

struct GraphAnalysis {
  uint32_t side = 0, levels = 0, channels = 0, K = 0;
  std::vector<GaussianStack> stacks;                             // per exemplar
  std::vector<std::vector<std::vector<StackLevel>>> admissible;  // [exemplar][level]
  // [((exemplar * levels + level) * side + y) * side + x) * K + c]
  std::vector<SynthCandidate> candidates;
  std::vector<float> transfer;        // the same index * channels + channel
  std::vector<double> kept_variance;  // per (exemplar, level): PCA variance kept (1 for a level without candidates)
  // Sec. 5.4: per synthesis level (each stored set of formats/admissible_levels.h superexemplar_levels), the PCA
  // of the 5 x 5 neighbourhoods of every stack level of that red depth, kSynthesisPcaComponents components: the
  // basis a renderer projects neighbourhoods with to match them in a few dimensions (our CPU synthesis matches
  // in full).
  SuperexemplarLevels superexemplar;
  std::vector<NeighbourhoodPca> synthesis_pca;

  size_t candidate_index(uint32_t exemplar, uint32_t level, uint32_t x, uint32_t y) const {
    return ((size_t(exemplar * levels + level) * side + y) * side + x) * K;
  }
};

// The 5 x 5 neighbourhood of texel (x, y) of a stack level at spacing h, toroidal: 25 x channels values, row by row.
void stack_neighbourhood(const Image& level, uint32_t h, uint32_t x, uint32_t y, float* out);

// exemplars: one image per graph exemplar, all square, of one power-of-two side and channel count (the caller checks).
GraphAnalysis analyse_graph(const ExemplarGraph& graph, const std::vector<Image>& exemplars,
                            const GraphAnalysisOptions& options, Progress& progress);

}  // namespace mbk
