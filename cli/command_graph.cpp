// `microbake graph INPUT -o OUT.mbk [--candidates K] [--pca-components P]`: analyses an exemplar graph (.json) for
// multiscale synthesis ([Han08] thesis Secs. 5.2-5.3; asset kind `graph`, libbake/synth/graph_asset.h): Gaussian
// stacks, admissible levels, k-coherence candidate sets and their transfer functions.
#include <sstream>

#include "cli/baking_command.h"
#include "libbake/image/normal_map.h"
#include "libbake/synth/graph_asset.h"

namespace mbk::cli {
namespace {

class GraphCommand : public BakingCommand {
 public:
  GraphCommand() : BakingCommand("graph", "graph analysis asset (.mbk)") {}

 private:
  void add_inputs(CLI::App& app) override {
    app.add_option("INPUT", path_,
                   "Exemplar graph (.json): {\"exemplars\": [{\"id\", \"path\"}], \"root\": id, \"edges\": "
                   "[{\"source\", \"destination\", \"r\"}]}")
        ->required();
  }

  void load() override {
    graph_ = load_exemplar_graph(path_);
    exemplars_ = load_graph_exemplars(graph_, path_);
    record_ = {
        {"path", path_}, {"content_hash", file_content_hash(path_)}, {"bytes", std::filesystem::file_size(path_)}};
  }

  void bake(Progress& progress) override {
    GraphAnalysisOptions options;
    options.candidates = parameters().at("candidates");
    options.pca_components = parameters().at("pca_components");
    analysis_ = analyse_graph(graph_, exemplars_.images, options, progress);
    asset_ = graph_asset_writer(graph_, analysis_, options, record_, exemplars_.records);
  }

  std::string bake_stage() const override { return "analysis"; }

  std::string summary() const override {
    std::ostringstream s;
    s << graph_.exemplars.size() << " exemplars of " << analysis_.side << "x" << analysis_.side << ", "
      << graph_.edges.size() << " edges, " << analysis_.levels << " stack levels, K = " << analysis_.K;
    return s.str();
  }

  std::string path_;
  ExemplarGraph graph_;
  LoadedExemplars exemplars_;
  nlohmann::json record_;
  GraphAnalysis analysis_;
};

}  // namespace

std::unique_ptr<Command> make_graph_command() { return std::make_unique<GraphCommand>(); }

}  // namespace mbk::cli
