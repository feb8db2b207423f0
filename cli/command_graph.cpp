// `microbake graph GRAPH.json -o GRAPH.mbk [--candidates K] [--pca-components P]`: analyses an exemplar graph for
// multiscale synthesis ([Han08] thesis Secs. 5.2-5.3; asset kind `graph`, libbake/synth/graph_asset.h): Gaussian
// stacks, admissible levels, k-coherence candidate sets and their transfer functions.
#include <iomanip>
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/stage_timer.h"
#include "libbake/image/normal_map.h"
#include "libbake/synth/graph_asset.h"

namespace mbk::cli {
namespace {

class GraphCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("GRAPH", options_.graph,
                   "Exemplar graph (.json): {\"exemplars\": [{\"id\", \"path\"}], \"root\": id, \"edges\": "
                   "[{\"source\", \"destination\", \"r\"}]}")
        ->required();
    add_output_option(app, options_.output, "graph analysis asset (.mbk)");
    app.add_option("--candidates", options_.analysis.candidates,
                   "k-coherence candidates per stack texel, K (the thesis: 2)")
        ->check(CLI::Range(1u, 16u))
        ->default_val(2u);
    app.add_option("--pca-components", options_.analysis.pca_components,
                   "principal components of the 5 x 5 neighbourhoods the candidate search matches in")
        ->check(CLI::Range(1u, 100u))
        ->default_val(8u);
    add_run_options(app, options_.run);
  }

  void check() override {
    options_.output.require_extension(".mbk");
    options_.output.check_writable();
  }

  int run() override {
    options_.run.apply();
    Progress progress(options_.run.progress_mode());
    StageTimer timer;
    const ExemplarGraph graph = load_exemplar_graph(options_.graph);
    const LoadedExemplars exemplars = load_graph_exemplars(graph, options_.graph);
    const nlohmann::json graph_record = {{"path", options_.graph},
                                         {"content_hash", file_content_hash(options_.graph)},
                                         {"bytes", std::filesystem::file_size(options_.graph)}};
    const double load_seconds = timer.lap();
    const GraphAnalysis analysis = analyse_graph(graph, exemplars.images, options_.analysis, progress);
    const AssetWriter writer = graph_asset_writer(graph, analysis, options_.analysis, graph_record, exemplars.records);
    const double bake_seconds = timer.lap();
    options_.output.write_asset(writer);
    const double write_seconds = timer.lap();
    if (!options_.run.quiet)
      std::cout << std::fixed << std::setprecision(3) << "graph: wrote " << options_.output.path << " ("
                << graph.exemplars.size() << " exemplars of " << analysis.side << "x" << analysis.side << ", "
                << graph.edges.size() << " edges, " << analysis.levels << " stack levels, K = " << analysis.K
                << "); load " << load_seconds << " s, analysis " << bake_seconds << " s, write " << write_seconds
                << " s\n";
    return 0;
  }

 private:
  struct Options {
    std::string graph;
    OutputOption output;
    GraphAnalysisOptions analysis;
    RunOptions run;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_graph_command() { return std::make_unique<GraphCommand>(); }

}  // namespace mbk::cli
