// Asset kind 9, `graph`: the analysis of an exemplar graph for multiscale synthesis ([Han08] thesis Secs.
// 5.2.1-5.3; formats/graph_layout.h). formats/SPEC.md, "Kind 9: graph".
//
// Invariants `validate` checks, in this order (the first finding ends the check): parameters and graph metadata
// (19001), section types and shapes (19002), finite stacks and transfers (19003), every candidate either none (all
// four words 0xFFFFFFFF) or in range with its (exemplar, level) admissible for its stack level, recomputed from the
// recorded edges (19004), transfer offsets exactly 0 within one level of one exemplar and where there is no
// candidate (19005),
// finite synthesis PCA means and orthonormal bases (19006: |b_p . b_q - delta_pq| <= 1e-4, float storage).
#include <algorithm>
#include <cmath>

#include "formats/number_text.h"
#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/graph_layout.h"

namespace mbk {
namespace {

void check_graph(const Asset& a, std::vector<Finding>& out) {
  GraphLayout g;
  if (std::string problem = parse_graph_layout(a, g); !problem.empty()) {
    out.push_back(make_finding(msg::graph_bad_parameters, problem, {{"key", "parameters"}}));
    return;
  }
  if (std::string problem = check_graph_section_shapes(a, g); !problem.empty()) {
    out.push_back(make_finding(msg::graph_section_shape, problem));
    return;
  }
  const std::vector<float> stacks = a.read<float>(kGraphStacksSection), transfer = a.read<float>(kGraphTransferSection);
  for (const auto& [name, values] :
       {std::pair{kGraphStacksSection, &stacks}, std::pair{kGraphTransferSection, &transfer}})
    for (size_t i = 0; i < values->size(); ++i)
      if (!std::isfinite((*values)[i])) {
        out.push_back(make_finding(msg::graph_non_finite, "'" + std::string(name) + "' element " + number_text(i),
                                   {{"section", name}, {"index", i}}));
        return;
      }
  // The per-synthesis-level PCA: finite means, orthonormal bases (float storage: 1e-4).
  const std::vector<float> means = a.read<float>(kGraphPcaMeanSection), bases = a.read<float>(kGraphPcaBasisSection);
  const size_t dims = 25 * size_t(g.channels), P = g.synthesis_pca_components;
  for (float v : means)
    if (!std::isfinite(v)) {
      out.push_back(make_finding(msg::graph_bad_pca, "non-finite synthesis PCA mean"));
      return;
    }
  for (size_t d = 0; d < g.depths; ++d)
    for (size_t p = 0; p < P; ++p)
      for (size_t q = p; q < P; ++q) {
        double dot = 0.0;
        for (size_t i = 0; i < dims; ++i) dot += double(bases[(d * dims + i) * P + p]) * bases[(d * dims + i) * P + q];
        if (!(std::abs(dot - (p == q ? 1.0 : 0.0)) <= 1e-4)) {
          out.push_back(make_finding(msg::graph_bad_pca,
                                     "synthesis level " + number_text(d) + ": components " + number_text(p) + " and " +
                                         number_text(q) + " have dot product " + number_text(dot),
                                     {{"depth", d}}));
          return;
        }
      }
  const std::vector<uint32_t> candidates = a.read<uint32_t>(kGraphCandidatesSection);
  const auto admissible = admissible_levels(g.exemplars, g.edges, g.levels);
  const size_t texels = size_t(g.side) * g.side;
  for (size_t slot = 0; slot < candidates.size() / 4; ++slot) {
    const size_t texel = slot / g.candidates;
    const uint32_t i = uint32_t(texel / (texels * g.levels)), k = uint32_t(texel / texels % g.levels);
    const uint32_t* c = &candidates[slot * 4];
    const bool none = std::all_of(c, c + 4, [](uint32_t v) { return v == kGraphNoCandidate; });
    const auto& allowed = admissible[i][k];
    if (!none && (c[2] >= g.side || c[3] >= g.side ||
                  std::find(allowed.begin(), allowed.end(), StackLevel{c[0], c[1]}) == allowed.end())) {
      out.push_back(make_finding(msg::graph_bad_candidate,
                                 "candidate " + number_text(slot % g.candidates) + " of exemplar " + number_text(i) +
                                     " level " + number_text(k) + " texel " + number_text(texel % texels) + " is (" +
                                     number_text(c[0]) + ", " + number_text(c[1]) + ", " + number_text(c[2]) + ", " +
                                     number_text(c[3]) + ")",
                                 {{"slot", slot}}));
      return;
    }
    if (none || (c[0] == i && c[1] >= k))  // a loop (c[1] < k) carries a transfer, libbake/synth/loop_transitions.h
      for (uint32_t ch = 0; ch < g.channels; ++ch)
        if (transfer[slot * g.channels + ch] != 0.0f) {
          out.push_back(make_finding(msg::graph_bad_transfer,
                                     "candidate slot " + number_text(slot) + " channel " + number_text(ch) +
                                         " has offset " + number_text(transfer[slot * g.channels + ch]),
                                     {{"slot", slot}}));
          return;
        }
  }
}

}  // namespace

AssetKind graph_kind() {
  AssetKind k;
  k.id = kGraphKindId;
  k.name = "graph";
  k.summary = "exemplar-graph analysis: Gaussian stacks, k-coherence candidate sets and transfer functions";
  k.required_sections = {{kGraphStacksSection, {ElementType::f32}, 5},
                         {kGraphCandidatesSection, {ElementType::u32}, 6},
                         {kGraphTransferSection, {ElementType::f32}, 6},
                         {kGraphPcaMeanSection, {ElementType::f32}, 2},
                         {kGraphPcaBasisSection, {ElementType::f32}, 3}};
  k.knows_section = [](const std::string& name) {
    for (const char* s : {kGraphStacksSection, kGraphCandidatesSection, kGraphTransferSection, kGraphPcaMeanSection,
                          kGraphPcaBasisSection})
      if (name == s) return true;
    return false;
  };
  k.check_invariants = check_graph;
  return k;
}

}  // namespace mbk
