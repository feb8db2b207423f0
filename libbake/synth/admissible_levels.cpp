// Admissible candidate levels (see admissible_levels.h).
#include "libbake/synth/admissible_levels.h"

#include <algorithm>

namespace mbk {

std::vector<std::vector<std::vector<StackLevel>>> admissible_levels(const ExemplarGraph& graph, uint32_t levels) {
  const uint32_t L = levels - 1;
  std::vector<GraphEdge> edges = graph.edges;
  for (uint32_t i = 0; i < graph.exemplars.size(); ++i) edges.push_back({i, i, 0});  // implicit self-loops
  std::vector<std::vector<std::vector<StackLevel>>> a(graph.exemplars.size(),
                                                      std::vector<std::vector<StackLevel>>(levels));
  for (const GraphEdge& e : edges)
    for (uint32_t k = e.r; k <= L; ++k)
      if (k - e.r < L) a[e.source][k].push_back({e.destination, k - e.r});
  for (auto& per_exemplar : a)
    for (auto& set : per_exemplar) {
      std::sort(set.begin(), set.end());
      set.erase(std::unique(set.begin(), set.end()), set.end());
    }
  return a;
}

}  // namespace mbk
