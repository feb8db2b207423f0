// Admissible candidate levels (see admissible_levels.h).
#include "formats/admissible_levels.h"

#include <algorithm>

namespace mbk {

std::vector<std::vector<std::vector<StackLevel>>> admissible_levels(uint32_t exemplars,
                                                                    const std::vector<GraphEdge>& explicit_edges,
                                                                    uint32_t levels) {
  const uint32_t L = levels - 1;
  std::vector<GraphEdge> edges = explicit_edges;
  for (uint32_t i = 0; i < exemplars; ++i) edges.push_back({i, i, 0});  // implicit self-loops
  std::vector<std::vector<std::vector<StackLevel>>> a(exemplars, std::vector<std::vector<StackLevel>>(levels));
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
