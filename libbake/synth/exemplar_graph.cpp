// Reading and checking exemplar graphs (see exemplar_graph.h).
#include "libbake/synth/exemplar_graph.h"

#include <map>
#include <set>

#include "formats/atomic_file.h"
#include "formats/error.h"
#include "libbake/image/normal_map.h"
#include "libbake/scene/json_fields.h"

namespace mbk {

ExemplarGraph parse_exemplar_graph(const nlohmann::json& json, const std::string& file,
                                   const std::filesystem::path& folder) {
  const auto fail = [&](const std::string& what, const std::string& path) {
    throw Error(ExitCode::invalid_input, what, file + ": " + (path.empty() ? "(top level)" : path));
  };
  try {
    ExemplarGraph g;
    JsonObjectReader top(json, "");
    const nlohmann::json& exemplars = top.required("exemplars");
    if (!exemplars.is_array() || exemplars.empty()) fail("expected a non-empty array of exemplars", "exemplars");
    std::map<std::string, uint32_t> index;
    for (size_t i = 0; i < exemplars.size(); ++i) {
      JsonObjectReader e(exemplars[i], json_index_path("exemplars", i));
      ExemplarGraph::Exemplar x;
      x.id = json_string(e.required("id"), e.child("id"));
      if (x.id.empty()) fail("empty id", e.child("id"));
      if (!index.emplace(x.id, uint32_t(i)).second) fail("duplicate exemplar id '" + x.id + "'", e.child("id"));
      x.path_as_written = json_string(e.required("path"), e.child("path"));
      if (x.path_as_written.empty()) fail("empty path", e.child("path"));
      const std::filesystem::path p(x.path_as_written);
      x.path = p.is_absolute() ? p : folder / p;
      e.reject_unknown_keys();
      g.exemplars.push_back(std::move(x));
    }
    const auto id_of = [&](const nlohmann::json& v, const std::string& path) {
      const std::string id = json_string(v, path);
      const auto it = index.find(id);
      if (it == index.end()) {
        std::string known;
        for (const auto& [name, k] : index) known += (known.empty() ? "" : ", ") + name;
        fail("unknown exemplar '" + id + "' (known: " + known + ")", path);
      }
      return it->second;
    };
    g.root = id_of(top.required("root"), "root");
    const nlohmann::json* edges = top.optional("edges");
    if (edges && !edges->is_array()) fail("expected an array of edges", "edges");
    std::set<std::tuple<uint32_t, uint32_t, uint32_t>> seen;
    for (size_t i = 0; edges && i < edges->size(); ++i) {
      JsonObjectReader e((*edges)[i], json_index_path("edges", i));
      GraphEdge edge;
      edge.source = id_of(e.required("source"), e.child("source"));
      edge.destination = id_of(e.required("destination"), e.child("destination"));
      edge.r = json_uint(e.required("r"), e.child("r"), 0, 12);
      e.reject_unknown_keys();
      if (edge.source == edge.destination && edge.r == 0)
        fail("an edge from an exemplar to itself with r = 0 is implicit; remove it", e.path());
      if (!seen.emplace(edge.source, edge.destination, edge.r).second) fail("duplicate edge", e.path());
      g.edges.push_back(edge);
    }
    if (const nlohmann::json* v = top.optional("normal_map")) g.normal_map = json_bool(*v, "normal_map");
    if (const nlohmann::json* v = top.optional("convention")) {
      if (!g.normal_map) fail("'convention' applies to normal-map graphs only (\"normal_map\": true)", "convention");
      g.convention = convention_request_name(parse_convention_request(json_string(*v, "convention")));
    }
    top.reject_unknown_keys();
    // Reachability from the root along the edges (Sec. 5.2: synthesis starts at the root and follows edges).
    std::vector<bool> reached(g.exemplars.size(), false);
    std::vector<uint32_t> stack{g.root};
    reached[g.root] = true;
    while (!stack.empty()) {
      const uint32_t at = stack.back();
      stack.pop_back();
      for (const GraphEdge& e : g.edges)
        if (e.source == at && !reached[e.destination]) reached[e.destination] = true, stack.push_back(e.destination);
    }
    for (size_t i = 0; i < reached.size(); ++i)
      if (!reached[i])
        fail("exemplar '" + g.exemplars[i].id + "' is not reachable from the root '" + g.exemplars[g.root].id + "'",
             json_index_path("exemplars", i));
    return g;
  } catch (const Error& e) {
    if (e.where().rfind(file + ": ", 0) == 0) throw;
    throw Error(e.code(), e.what(), file + ": " + (e.where().empty() ? "(top level)" : e.where()));
  }
}

ExemplarGraph load_exemplar_graph(const std::filesystem::path& file) {
  const std::vector<uint8_t> bytes = read_file_bytes(file);
  return parse_exemplar_graph_text(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), file);
}

ExemplarGraph parse_exemplar_graph_text(std::string_view text, const std::filesystem::path& file) {
  const nlohmann::json json = parse_json_strict(text, file.string());
  std::filesystem::path folder = file.parent_path();
  if (folder.empty()) folder = ".";
  return parse_exemplar_graph(json, file.string(), folder);
}

void check_edge_scales(const ExemplarGraph& graph, uint32_t L, const std::string& file) {
  for (size_t i = 0; i < graph.edges.size(); ++i)
    if (graph.edges[i].r >= L)
      throw Error(ExitCode::invalid_input,
                  "r = " + std::to_string(graph.edges[i].r) + " must be below r_max = L = " + std::to_string(L) +
                      " for exemplars of 2^L texels a side (r_max = L keeps source and destination scales overlapping)",
                  file + ": " + json_index_path("edges", i) + ".r");
}

}  // namespace mbk
