// Test fixtures for the `graph` kind: a small valid asset built by hand (independently of the analysis): two 4 x 4
// one-channel exemplars (L = 2, three stack levels), one edge 0 -> 1 with r = 1, K = 1. Each texel's candidate is
// texel (0, 0) of the first admissible level of its stack level (none where there is none); transfers 0.1 across
// exemplars, 0 within one. Corruptions edit the parts before writing, one per graph finding
// (tests/formats/corrupt_fixtures_test.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "formats/asset_writer.h"
#include "formats/graph_layout.h"

namespace mbk::test {

struct GraphParts {
  nlohmann::json metadata;
  std::vector<float> stacks, transfer, pca_mean, pca_basis;
  std::vector<uint32_t> candidates;
};

inline GraphParts valid_graph_parts() {
  GraphParts p;
  const uint32_t E = 2, levels = 3, m = 4, K = 1;
  p.metadata = {
      {"inputs", nlohmann::json::array()},
      {"parameters",
       {{"side", m}, {"levels", levels}, {"channels", 1}, {"exemplars", E}, {"candidates", K}, {"pca_components", 8}}},
      {"graph", {{"ids", {"a", "b"}}, {"root", 0}, {"edges", {{0, 1, 1}}}}},
      {"superexemplar", {{"sets", {{{0, 0}}, {{0, 1}, {1, 0}}, {{0, 2}, {1, 0}, {1, 1}}}}, {"repeat_from", 2}}},
      {"conventions", nlohmann::json::object()},
      {"statistics", nlohmann::json::object()}};
  for (uint32_t i = 0; i < E * levels * m * m; ++i) p.stacks.push_back(0.25f + 0.01f * float(i % 7));
  const auto admissible = admissible_levels(E, {{0, 1, 1}}, levels);
  for (uint32_t i = 0; i < E; ++i)
    for (uint32_t k = 0; k < levels; ++k)
      for (uint32_t t = 0; t < m * m; ++t) {
        if (admissible[i][k].empty()) {
          p.candidates.insert(p.candidates.end(), 4, kGraphNoCandidate);
          p.transfer.push_back(0.0f);
          continue;
        }
        const StackLevel& l = admissible[i][k].front();
        p.candidates.insert(p.candidates.end(), {l.exemplar, l.level, 0u, 0u});
        p.transfer.push_back(l.exemplar == i ? 0.0f : 0.1f);
      }
  // Three stored synthesis levels, 25 dimensions, P = 2: the first two unit axes.
  p.metadata["parameters"]["synthesis_pca_components"] = 2;
  p.pca_mean.assign(3 * 25, 0.5f);
  p.pca_basis.assign(3 * 25 * 2, 0.0f);
  for (size_t d = 0; d < 3; ++d) {
    p.pca_basis[(d * 25 + 0) * 2 + 0] = 1.0f;
    p.pca_basis[(d * 25 + 1) * 2 + 1] = 1.0f;
  }
  return p;
}

inline std::vector<uint8_t> graph_bytes(const std::function<void(GraphParts&)>& corrupt = {}) {
  GraphParts p = valid_graph_parts();
  if (corrupt) corrupt(p);
  AssetWriter w("graph", p.metadata);
  w.add(kGraphStacksSection, {2, 3, 4, 4, 1}, p.stacks);
  w.add(kGraphCandidatesSection, {2, 3, 4, 4, 1, 4}, p.candidates);
  w.add(kGraphTransferSection, {2, 3, 4, 4, 1, 1}, p.transfer);
  w.add(kGraphPcaMeanSection, {3, 25}, p.pca_mean);
  w.add(kGraphPcaBasisSection, {3, 25, 2}, p.pca_basis);
  return w.serialize();
}

}  // namespace mbk::test
