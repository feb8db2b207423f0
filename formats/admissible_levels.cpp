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

const std::vector<StackLevel>& SuperexemplarLevels::at(uint64_t t) const {
  if (t < sets.size()) return sets[size_t(t)];
  const uint64_t period = sets.size() - repeat_from;
  return sets[size_t(repeat_from + (t - repeat_from) % period)];
}

SuperexemplarLevels superexemplar_levels(uint32_t exemplars, const std::vector<GraphEdge>& edges, uint32_t levels,
                                         uint32_t root) {
  const auto admissible = admissible_levels(exemplars, edges, levels);
  const uint32_t L = levels - 1;
  const auto closure = [&](std::vector<StackLevel> set) {
    for (size_t n = 0; n < set.size(); ++n)  // breadth-first over black edges; `set` grows while walked
      for (const StackLevel& d : admissible[set[n].exemplar][set[n].level])
        if (std::find(set.begin(), set.end(), d) == set.end()) set.push_back(d);
    std::sort(set.begin(), set.end());
    return set;
  };
  SuperexemplarLevels s;
  std::vector<StackLevel> current = closure({{root, 0}});
  while (true) {
    const auto seen = std::find(s.sets.begin(), s.sets.end(), current);
    if (seen != s.sets.end()) {
      s.repeat_from = uint32_t(seen - s.sets.begin());
      return s;
    }
    s.sets.push_back(current);
    std::vector<StackLevel> next;
    for (const StackLevel& l : current)
      if (l.level < L)
        next.push_back({l.exemplar, l.level + 1});
      else if (admissible[l.exemplar][L].empty())
        next.push_back(l);  // stuck at its finest level: magnified
    current = closure(std::move(next));
  }
}

}  // namespace mbk
