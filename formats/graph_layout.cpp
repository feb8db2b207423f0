// Reading the `graph` asset's layout (see graph_layout.h).
#include "formats/graph_layout.h"

#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/error.h"

namespace mbk {

std::vector<uint64_t> GraphLayout::stacks_shape() const { return {exemplars, levels, side, side, channels}; }
std::vector<uint64_t> GraphLayout::candidates_shape() const { return {exemplars, levels, side, side, candidates, 4}; }
std::vector<uint64_t> GraphLayout::transfer_shape() const {
  return {exemplars, levels, side, side, candidates, channels};
}

namespace {

// A top-level metadata member, or null when the file lacks it (the container requires only the common members, and
// json's const operator[] must never be given a missing key).
const nlohmann::json& metadata_member(const Asset& asset, const char* key) {
  static const nlohmann::json kMissing;
  const auto it = asset.metadata().find(key);
  return it == asset.metadata().end() ? kMissing : *it;
}

}  // namespace

std::string parse_graph_layout(const Asset& asset, GraphLayout& g) {
  const nlohmann::json& p = asset.metadata()["parameters"];
  if (!p.is_object()) return "parameters missing";
  for (const char* key :
       {"side", "levels", "channels", "exemplars", "candidates", "pca_components", "synthesis_pca_components"})
    if (!p.contains(key) || !p[key].is_number_unsigned() || p[key].get<uint64_t>() > 0xFFFFFFFFu)
      return std::string("parameters.") + key + " missing or not an unsigned 32-bit integer";
  g.side = p["side"];
  g.levels = p["levels"];
  g.channels = p["channels"];
  g.exemplars = p["exemplars"];
  g.candidates = p["candidates"];
  g.pca_components = p["pca_components"];
  g.synthesis_pca_components = p["synthesis_pca_components"];
  if (g.side < 4 || g.side > 4096 || (g.side & (g.side - 1)) != 0) return "side must be a power of two in [4, 4096]";
  uint32_t L = 0;
  while ((1u << L) < g.side) ++L;
  if (g.levels != L + 1) return "levels must be log2(side) + 1 = " + std::to_string(L + 1);
  if (g.channels < 1 || g.channels > 4) return "channels must be 1..4";
  if (g.exemplars < 1 || g.exemplars > 1024) return "exemplars must be 1..1024";
  if (g.candidates < 1 || g.candidates > 16) return "candidates must be 1..16";
  if (g.synthesis_pca_components < 1 || g.synthesis_pca_components > 25 * g.channels)
    return "synthesis_pca_components must be 1..25 x channels";
  const nlohmann::json& graph = metadata_member(asset, "graph");
  if (!graph.is_object() || !graph.contains("ids") || !graph["ids"].is_array() || graph["ids"].size() != g.exemplars)
    return "graph.ids must list one id per exemplar";
  g.ids.clear();
  for (const auto& id : graph["ids"]) {
    if (!id.is_string()) return "graph.ids must be strings";
    g.ids.push_back(id);
  }
  if (!graph.contains("root") || !graph["root"].is_number_unsigned() || graph["root"].get<uint64_t>() >= g.exemplars)
    return "graph.root must be an exemplar index";
  g.root = graph["root"];
  const nlohmann::json& super = metadata_member(asset, "superexemplar");
  if (!super.is_object() || !super.contains("sets") || !super["sets"].is_array() || super["sets"].empty() ||
      super["sets"].size() > 100000 || !super.contains("repeat_from") || !super["repeat_from"].is_number_unsigned() ||
      super["repeat_from"].get<uint64_t>() >= super["sets"].size())
    return "superexemplar must hold a non-empty array of sets and repeat_from below their count";
  g.depths = uint32_t(super["sets"].size());
  g.normal_map = graph.value("normal_map", nlohmann::json(false)).is_boolean() && graph.value("normal_map", false);
  if (!graph.contains("edges") || !graph["edges"].is_array()) return "graph.edges must be an array";
  g.edges.clear();
  for (const auto& e : graph["edges"]) {
    if (!e.is_array() || e.size() != 3) return "graph.edges entries must be [source, destination, r]";
    for (const auto& v : e)
      if (!v.is_number_unsigned()) return "graph.edges entries must be unsigned integers";
    const uint64_t s = e[0], d = e[1], r = e[2];
    if (s >= g.exemplars || d >= g.exemplars) return "graph.edges names an exemplar out of range";
    if (r >= L) return "graph.edges has r = " + std::to_string(r) + ", not below L = " + std::to_string(L);
    g.edges.push_back({uint32_t(s), uint32_t(d), uint32_t(r)});
  }
  return {};
}

std::string check_graph_section_shapes(const Asset& asset, const GraphLayout& g) {
  const std::pair<const char*, std::pair<ElementType, std::vector<uint64_t>>> expected[] = {
      {kGraphStacksSection, {ElementType::f32, g.stacks_shape()}},
      {kGraphCandidatesSection, {ElementType::u32, g.candidates_shape()}},
      {kGraphTransferSection, {ElementType::f32, g.transfer_shape()}},
      {kGraphPcaMeanSection, {ElementType::f32, g.pca_mean_shape()}},
      {kGraphPcaBasisSection, {ElementType::f32, g.pca_basis_shape()}}};
  for (const auto& [name, type_shape] : expected) {
    const SectionInfo& s = asset.section(name);
    if (s.type != type_shape.first || s.shape != type_shape.second)
      return "section '" + std::string(name) + "' has the wrong type or shape for the parameters";
  }
  return {};
}

GraphTables read_graph_tables(const Asset& asset) {
  if (asset.kind().name != "graph")
    throw Error(ExitCode::invalid_input, "expected a 'graph' asset, found '" + std::string(asset.kind().name) + "'",
                asset.where());
  GraphTables t;
  std::string problem = parse_graph_layout(asset, t.layout);
  if (problem.empty()) problem = check_graph_section_shapes(asset, t.layout);
  if (!problem.empty()) throw Error(ExitCode::invalid_input, "malformed graph asset: " + problem, asset.where());
  // Synthesis indexes stacks with the candidate words: Asset::open/parse already refused a file that fails the
  // kind's invariants (a resealed, edited candidate) rather than let it be read out of bounds.
  t.stacks = asset.read<float>(kGraphStacksSection);
  t.candidates = asset.read<uint32_t>(kGraphCandidatesSection);
  t.transfer = asset.read<float>(kGraphTransferSection);
  return t;
}

}  // namespace mbk
