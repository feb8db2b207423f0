// The exemplar graph of [Han08] (C. Han's thesis, ch. 4; Han, Risser, Ramamoorthi, Grinspun, "Multiscale texture
// synthesis", SIGGRAPH 2008): a few small exemplars linked by scale relations describing a texture of unbounded
// extent and detail. Sec. 4.1: a reflexive, directed graph; an edge (i, j, r) says a texel of exemplar i is 2^r times
// as wide as a texel of exemplar j; every exemplar has an implicit self-loop with r = 0; loops are allowed (a
// self-loop with r > 0 is an infinite zoom); r < r_max so that source and destination scales overlap.
//
// The file (JSON; unknown and duplicate keys are errors naming their path):
//   {"exemplars": [{"id": "rock", "path": "rock.png"}, ...],   paths relative to the graph file
//    "root": "rock",                                            the coarsest-level start of synthesis
//    "edges": [{"source": "rock", "destination": "pebbles", "r": 2}, ...],
//    "normal_map": false,                                       optional: the exemplars are normal maps
//    "convention": "auto"}                                      optional, for normal maps: auto (default), +Y/-Y
// Normal-map exemplars are decoded and renormalised as every baker reads normal maps (libbake/image/normal_map.h),
// analysed as vectors, and synthesized as unit normals.
// Exemplars are images OpenImageIO reads (colour images or normal maps), all of one size m x m with m = 2^L a
// power of two in [16, 1024] (Sec. 4.1 assumes m = 2^L; below 16 the 5 x 5 neighbourhoods wrap round the torus,
// above 1024 the analysis holds gigabytes per exemplar) and one channel count. r is an integer, 0 <= r < L
// (r_max = L: with r = L only the source's finest level would see the destination's coarsest, too little
// overlap to reconstruct the scales between, Sec. 4.1); an explicit edge
// (i, i, 0) repeats the implicit one and is refused, as are duplicate edges. Every exemplar must be reachable from
// the root.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/admissible_levels.h"

namespace mbk {

struct ExemplarGraph {
  struct Exemplar {
    std::string id;
    std::string path_as_written;
    std::filesystem::path path;  // resolved against the graph file's folder
  };
  std::vector<Exemplar> exemplars;
  uint32_t root = 0;
  std::vector<GraphEdge> edges;  // as listed, implicit self-loops not included
  bool normal_map = false;
  std::string convention = "auto";  // of normal-map exemplars: auto, +Y or -Y
};

// Parses and checks the structure (ids, root, edges, reachability; not the images). Error(invalid_input) naming
// `file` and the JSON path. `folder` resolves relative exemplar paths.
ExemplarGraph parse_exemplar_graph(const nlohmann::json& graph, const std::string& file,
                                   const std::filesystem::path& folder);
// Reads and parses a graph file. Error(io_failure) when unreadable, invalid_input when malformed.
ExemplarGraph load_exemplar_graph(const std::filesystem::path& file);
// The same from the file's bytes (`file` names it and its folder starts relative paths; nothing is read from disk).
ExemplarGraph parse_exemplar_graph_text(std::string_view text, const std::filesystem::path& file);

// Checks r < L (r_max = L for exemplars of 2^L texels a side) for every edge; Error(invalid_input) naming the edge.
void check_edge_scales(const ExemplarGraph& graph, uint32_t L, const std::string& file);

}  // namespace mbk
