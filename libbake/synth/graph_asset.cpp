// Baking the graph asset (see graph_asset.h).
#include "libbake/synth/graph_asset.h"

#include <cmath>

#include "formats/error.h"
#include "formats/graph_layout.h"
#include "libbake/image/normal_map.h"

namespace mbk {

LoadedExemplars load_graph_exemplars(const ExemplarGraph& graph, const std::string& graph_file) {
  LoadedExemplars out;
  for (const ExemplarGraph::Exemplar& e : graph.exemplars) {
    const std::string where = e.path.string() + " (exemplar '" + e.id + "' of " + graph_file + ")";
    ImageFileInfo info;
    const ImageHeader header = read_image_header_within(e.path, 1024, "exemplar '" + e.id + "'");
    Image im;
    nlohmann::json record;
    if (graph.normal_map) {  // decoded and renormalised like every baker's input; stored as vectors
      NormalMapLoadOptions options;
      options.convention = parse_convention_request(graph.convention);
      const LoadedNormalMap loaded = load_normal_map(e.path, options);
      im = {loaded.map.width, loaded.map.height, 3, {}};
      for (const Vec3f& n : loaded.map.texels) im.pixels.insert(im.pixels.end(), {n.x(), n.y(), n.z()});
      record = loaded.record.to_json();
      record["path"] = e.path_as_written;
    } else {
      im = load_image(e.path, &info);
      record = {{"path", e.path_as_written},
                {"content_hash", file_content_hash(e.path)},
                {"bytes", std::filesystem::file_size(e.path)},
                {"width", header.width},
                {"height", header.height},
                {"channels", info.file_channels},
                {"pixel_format", info.pixel_format}};
    }
    if (im.width != im.height || im.width < 16 || exact_log2(im.width) < 0)
      throw Error(ExitCode::invalid_input,
                  "exemplar is " + std::to_string(im.width) + "x" + std::to_string(im.height) +
                      "; exemplars must be square with a power-of-two side in [16, 1024]",
                  where);
    if (im.channels < 1 || im.channels > 4)
      throw Error(ExitCode::invalid_input, "exemplar has " + std::to_string(im.channels) + " channels (1..4)", where);
    if (!out.images.empty() && (im.width != out.images[0].width || im.channels != out.images[0].channels))
      throw Error(ExitCode::invalid_input,
                  "exemplar is " + std::to_string(im.width) + "x" + std::to_string(im.height) + " with " +
                      std::to_string(im.channels) + " channels, but '" + graph.exemplars[0].id + "' is " +
                      std::to_string(out.images[0].width) + "x" + std::to_string(out.images[0].width) + " with " +
                      std::to_string(out.images[0].channels) +
                      " channels: every exemplar of a graph has one size and channel count",
                  where);
    for (size_t i = 0; i < im.pixels.size(); ++i)
      if (!std::isfinite(im.pixels[i]))
        throw Error(ExitCode::invalid_input,
                    "non-finite value at texel (" + std::to_string(i / im.channels % im.width) + ", " +
                        std::to_string(i / im.channels / im.width) + ")",
                    where);
    out.records.push_back(std::move(record));
    out.images.push_back(std::move(im));
  }
  check_edge_scales(graph, uint32_t(exact_log2(out.images[0].width)), graph_file);
  return out;
}

namespace {

// Metadata "graph": the exemplars' ids, the root, the edges (source, destination, r) and whether they are normal maps.
nlohmann::json graph_json(const ExemplarGraph& graph) {
  nlohmann::json ids = nlohmann::json::array(), edges = nlohmann::json::array();
  for (const auto& e : graph.exemplars) ids.push_back(e.id);
  for (const GraphEdge& e : graph.edges) edges.push_back({e.source, e.destination, e.r});
  return {{"ids", ids}, {"root", graph.root}, {"edges", edges}, {"normal_map", graph.normal_map}};
}

// Metadata "superexemplar": each set's (exemplar, level) stack levels and the level the sets repeat from.
nlohmann::json superexemplar_json(const SuperexemplarLevels& super) {
  nlohmann::json sets = nlohmann::json::array();
  for (const auto& set : super.sets) {
    nlohmann::json levels = nlohmann::json::array();
    for (const StackLevel& l : set) levels.push_back({l.exemplar, l.level});
    sets.push_back(levels);
  }
  return {{"sets", sets}, {"repeat_from", super.repeat_from}};
}

// Metadata "statistics": filled and empty candidate slots, how many candidates lie in another exemplar and their
// mean absolute transfer offset, and the smallest PCA variance kept.
nlohmann::json graph_statistics(const GraphAnalysis& a) {
  size_t across = 0, filled = 0;
  double offset = 0.0;
  for (size_t s = 0; s < a.candidates.size(); ++s) {
    if (a.candidates[s].exemplar == kNoCandidate) continue;
    ++filled;
    if (a.candidates[s].exemplar != uint32_t(s / a.K / (size_t(a.side) * a.side) / a.levels)) {
      ++across;
      for (uint32_t c = 0; c < a.channels; ++c) offset += std::abs(a.transfer[s * a.channels + c]);
    }
  }
  double min_kept = 1.0;
  for (double v : a.kept_variance) min_kept = std::min(min_kept, v);
  return nlohmann::json{{"candidates", filled},
                        {"empty_candidate_slots", a.candidates.size() - filled},
                        {"across_exemplars", across},
                        {"mean_abs_transfer_across", across ? offset / double(across * a.channels) : 0.0},
                        {"min_pca_variance_kept", min_kept}};
}

}  // namespace

AssetWriter graph_asset_writer(const ExemplarGraph& graph, const GraphAnalysis& a, const GraphAnalysisOptions& options,
                               const nlohmann::json& graph_record, const nlohmann::json& exemplar_records) {
  GraphLayout layout;
  layout.side = a.side;
  layout.levels = a.levels;
  layout.channels = a.channels;
  layout.exemplars = uint32_t(graph.exemplars.size());
  layout.candidates = a.K;
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({graph_record});
  for (const auto& r : exemplar_records) metadata["inputs"].push_back(r);
  metadata["parameters"] = {{"synthesis_pca_components", kSynthesisPcaComponents},
                            {"side", a.side},
                            {"levels", a.levels},
                            {"channels", a.channels},
                            {"exemplars", layout.exemplars},
                            {"candidates", a.K},
                            {"pca_components", options.pca_components}};
  metadata["graph"] = graph_json(graph);
  metadata["superexemplar"] = superexemplar_json(a.superexemplar);
  metadata["conventions"] = {
      {"stacks",
       "level k of L + 1: the exemplar filtered with a periodic Gaussian of standard deviation 2^(L-k-1) "
       "texels; level L the exemplar; a texel of level k spans h_k = 2^(L-k) exemplar texels"},
      {"candidates",
       "(exemplar, level, x, y) per candidate, best first, 5 x 5 neighbourhoods at spacings h_k, h_l, "
       "toroidal; 0xFFFFFFFF x 4 for none"},
      {"transfer", "constant offset b: destination + b matches the source ([Han08] Sec. 5.3)"}};
  if (graph.normal_map)
    metadata["conventions"]["normal_convention"] =
        "+Y (the exemplars decoded as their inputs' convention; requested " + graph.convention + ")";
  metadata["statistics"] = graph_statistics(a);
  AssetWriter writer("graph", std::move(metadata));
  std::vector<float> stacks;
  for (const GaussianStack& s : a.stacks)
    for (const Image& level : s.images) stacks.insert(stacks.end(), level.pixels.begin(), level.pixels.end());
  std::vector<uint32_t> candidates;
  candidates.reserve(a.candidates.size() * 4);
  for (const SynthCandidate& c : a.candidates) {
    const bool none = c.exemplar == kNoCandidate;
    for (uint32_t v : {c.exemplar, c.level, c.x, c.y}) candidates.push_back(none ? kGraphNoCandidate : v);
  }
  writer.add(kGraphStacksSection, layout.stacks_shape(), std::move(stacks));
  writer.add(kGraphCandidatesSection, layout.candidates_shape(), std::move(candidates));
  writer.add(kGraphTransferSection, layout.transfer_shape(), a.transfer);
  std::vector<float> means, bases;
  for (const NeighbourhoodPca& p : a.synthesis_pca) {
    for (Eigen::Index d = 0; d < p.mean.size(); ++d) means.push_back(float(p.mean[d]));
    for (Eigen::Index d = 0; d < p.basis.rows(); ++d)
      for (Eigen::Index c = 0; c < p.basis.cols(); ++c) bases.push_back(float(p.basis(d, c)));
  }
  layout.depths = uint32_t(a.synthesis_pca.size());
  layout.synthesis_pca_components = kSynthesisPcaComponents;
  writer.add(kGraphPcaMeanSection, layout.pca_mean_shape(), std::move(means));
  writer.add(kGraphPcaBasisSection, layout.pca_basis_shape(), std::move(bases));
  return writer;
}

}  // namespace mbk
