// Baking asset kind `graph` (formats/SPEC.md "Kind 9: graph"; formats/graph_layout.h) from an exemplar graph file:
// the exemplars are read (any image OpenImageIO reads, values as stored: integer formats in [0, 1], floats as they
// are; normal-map graphs decoded to unit +Y vectors as every baker reads normal maps), checked (one square power-of-two
// size in [16, 1024], one channel count in 1..4, finite values, every edge's r < L), analysed (graph_analysis.h) and
// written with their input records.
#pragma once

#include <filesystem>

#include "formats/asset_writer.h"
#include "libbake/synth/exemplar_graph.h"
#include "libbake/synth/graph_analysis.h"

namespace mbk {

struct LoadedExemplars {
  std::vector<Image> images;
  nlohmann::json records = nlohmann::json::array();  // one input record per exemplar, in graph order
};

// Error(invalid_input) naming the exemplar's file for the checks above; io_failure when a file is missing.
LoadedExemplars load_graph_exemplars(const ExemplarGraph& graph, const std::string& graph_file);

AssetWriter graph_asset_writer(const ExemplarGraph& graph, const GraphAnalysis& analysis,
                               const GraphAnalysisOptions& options, const nlohmann::json& graph_record,
                               const nlohmann::json& exemplar_records);

}  // namespace mbk
