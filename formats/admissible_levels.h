// Admissible candidate levels ([Han08] thesis Sec. 5.2.1.2): the stack levels where the correction step may look
// for a texel to replace one of stack level E^i_k,
//   A(E^i_k) = { E^j_l | (i, j, k - l) is an edge (the implicit self-loops (i, i, 0) included), 0 <= l < L },
// so the finest level L of every stack is never admissible (correction must move on to finer exemplars instead of
// getting stuck), and loops give candidates in the same exemplar (E^2_5 in A(E^2_6) for a self-loop r = 1).
// It lives in formats/ because the `graph` asset's validator checks stored candidates against it
// (formats/kind_graph.cpp) as the analysis (libbake/synth/graph_analysis.h) chooses them.
#pragma once

#include <compare>
#include <cstdint>
#include <vector>

namespace mbk {

struct GraphEdge {
  uint32_t source = 0, destination = 0;  // exemplar indices
  uint32_t r = 0;                        // the source texel is 2^r destination texels wide
};

struct StackLevel {
  uint32_t exemplar = 0, level = 0;
  bool operator==(const StackLevel&) const = default;
  auto operator<=>(const StackLevel&) const = default;
};

// [exemplar][k] -> the admissible levels, sorted (exemplar, level), for `exemplars` exemplars with `levels` = L + 1
// stack levels and the graph's explicit edges (indices < exemplars).
std::vector<std::vector<std::vector<StackLevel>>> admissible_levels(uint32_t exemplars,
                                                                    const std::vector<GraphEdge>& edges,
                                                                    uint32_t levels);

// The superexemplar's stack levels per synthesis level ([Han08] thesis Sec. 5.4, "red depth"): the stack levels a
// pixel of synthesis level t may point to. Level 0: the root's level 0 and every level reachable from it by
// correction steps (black edges: admissible levels, repeatedly); level t + 1: the upsampled levels of level t (red
// edges: k -> k + 1; a level L with no admissible level stays, as synthesis magnifies it) and their closure under
// correction. The sequence is eventually periodic (finitely many sets): sets[0..n-1] are the first n distinct sets
// and level t >= n has the set of repeat_from + (t - repeat_from) mod (n - repeat_from).
struct SuperexemplarLevels {
  std::vector<std::vector<StackLevel>> sets;  // each sorted
  uint32_t repeat_from = 0;
  const std::vector<StackLevel>& at(uint64_t t) const;
};
SuperexemplarLevels superexemplar_levels(uint32_t exemplars, const std::vector<GraphEdge>& edges, uint32_t levels,
                                         uint32_t root);

}  // namespace mbk
