// The data of the `graph` asset kind (formats/SPEC.md, "Kind 9: graph"): the analysis of an exemplar graph
// ([Han08] thesis Secs. 5.2.1-5.3; libbake/synth/graph_analysis.h), everything parallel synthesis reads.
//
// Metadata: parameters {"side": m, "levels": L + 1, "channels": C, "exemplars": E, "candidates": K,
// "pca_components": P}; "graph": {"ids": [E names], "root": index, "edges": [[source, destination, r], ...]}
// (explicit edges; the implicit self-loops r = 0 are not listed), "normal_map" (optional, default false: the
// exemplars were normal maps, stored as unit +Y vectors; synthesis renormalises its output).
// Sections (row-major, the last index fastest):
//   stacks      f32 [E, L + 1, m, m, C]     Gaussian stack levels, coarsest (k = 0) first; level L is the exemplar
//   candidates  u32 [E, L + 1, m, m, K, 4]  per stack texel (exemplar i, level k, row y, column x) its K candidates
//                                            (exemplar j, level l, x, y), best first; all four 0xFFFFFFFF where
//                                            there is none (a level with no admissible level); (j, l) always in
//                                            A(E^i_k) (admissible_levels.h)
//   transfer    f32 [E, L + 1, m, m, K, C]  the constant offset b of each candidate (destination + b matches the
//                                            source); 0 when j = i, and where there is no candidate
//   synthesis_pca_mean   f32 [D, 25 C]       per synthesis level t < D (the superexemplar's stored sets, metadata
//   synthesis_pca_basis  f32 [D, 25 C, P]    "superexemplar"), the mean and P orthonormal principal components of
//                                            the 5 x 5 neighbourhoods (row by row, channels fastest) of every stack
//                                            level of that red depth ([Han08] Sec. 5.4), largest variance first
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/admissible_levels.h"

namespace mbk {

class Asset;

inline constexpr uint32_t kGraphKindId = 9;
inline constexpr uint32_t kGraphNoCandidate = 0xFFFFFFFFu;
inline constexpr const char* kGraphStacksSection = "stacks";
inline constexpr const char* kGraphCandidatesSection = "candidates";
inline constexpr const char* kGraphTransferSection = "transfer";
inline constexpr const char* kGraphPcaMeanSection = "synthesis_pca_mean";
inline constexpr const char* kGraphPcaBasisSection = "synthesis_pca_basis";

struct GraphLayout {
  uint32_t side = 0, levels = 0, channels = 0, exemplars = 0, candidates = 0, pca_components = 0;
  uint32_t depths = 0;                    // stored superexemplar sets (synthesis levels before the period repeats)
  uint32_t synthesis_pca_components = 0;  // P of the per-synthesis-level PCA
  uint32_t root = 0;
  bool normal_map = false;  // graph.normal_map: stacks hold unit +Y tangent-space vectors (their blurs shorter)
  std::vector<std::string> ids;
  std::vector<GraphEdge> edges;
  std::vector<uint64_t> stacks_shape() const;
  std::vector<uint64_t> candidates_shape() const;
  std::vector<uint64_t> transfer_shape() const;
  std::vector<uint64_t> pca_mean_shape() const { return {depths, 25ull * channels}; }
  std::vector<uint64_t> pca_basis_shape() const { return {depths, 25ull * channels, synthesis_pca_components}; }
};

// Reads and checks the parameters and graph metadata (side a power of two in [4, 4096], levels = log2(side) + 1,
// channels 1..4, exemplars >= 1, candidates 1..16, ids one per exemplar, root and edge indices in range, r < L).
// Empty when sound, else what is wrong.
std::string parse_graph_layout(const Asset& asset, GraphLayout& layout);
// Empty when the three sections have the types and shapes above, else what differs.
std::string check_graph_section_shapes(const Asset& asset, const GraphLayout& layout);

// A graph asset read for synthesis: its layout and the three sections.
struct GraphTables {
  GraphLayout layout;
  std::vector<float> stacks, transfer;
  std::vector<uint32_t> candidates;
  // Index of texel (x, y) of level k of exemplar i in `stacks` (times channels) and, times K, in the
  // candidate slots.
  size_t texel(uint32_t i, uint32_t k, uint32_t x, uint32_t y) const {
    return ((size_t(i) * layout.levels + k) * layout.side + y) * layout.side + x;
  }
};
// Error(invalid_input) naming the file when the asset is not a well-formed graph asset or fails the kind's
// invariants (formats/kind_graph.cpp), so every index synthesis reads is in range.
GraphTables read_graph_tables(const Asset& asset);

}  // namespace mbk
