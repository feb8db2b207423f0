// `microbake histogram INPUT -o OUT.mbk [--method neural|exact] [--theta-bins K] [--phi-bins N] [--theta-binning B]
// [--features F] [--iterations I] [--batch B] [--seed S]`: bakes a normal map's adaptive (or uniform) bins
// ([Shah24] Sec. 4.1) and either the
// neural histogram (the default: a feature pyramid and small MLPs trained on the CPU, asset kind
// `neural_histogram`, libbake/histogram/neural_histogram_bake.h; [Shah24] Sec. 4.2) or the integral images of its
// per-bin counts, the exact binned P-NDF of any footprint (asset kind `histogram`,
// libbake/histogram/histogram_bake.h; [GGN18]).
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "libbake/histogram/histogram_asset.h"
#include "libbake/histogram/neural_histogram_asset.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk::cli {
namespace {

class HistogramCommand : public NormalMapBakingCommand {
 public:
  HistogramCommand() : NormalMapBakingCommand("histogram", "histogram or neural_histogram asset (.mbk)") {}

 private:
  void bake(Progress& progress) override {
    options_ = neural_histogram_bake_options(parameters());
    neural_ = parameters().at("method") == "neural";
    const uint64_t seed = histogram_seed(map().record.content_hash);
    if (neural_) {
      BakedNeuralHistogram baked = bake_neural_histogram(map().map, options_, seed, progress, input().path);
      bins_ = baked.bins;
      distinct_ = baked.theta.distinct_values;
      held_out_kl_ = baked.held_out_kl;
      asset_ = neural_histogram_asset_writer(map(), options_, seed, std::move(baked));
    } else {
      BakedHistogram baked = bake_histogram(map().map, options_.bins, seed, progress, input().path);
      bins_ = baked.bins;
      distinct_ = baked.theta.distinct_values;
      asset_ = histogram_asset_writer(map(), options_.bins, seed, std::move(baked));
    }
  }

  std::string summary() const override {
    std::ostringstream s;
    s << map_size() << ", " << bins_.theta_bins() << " x " << bins_.phi_bins << " bins";
    if (options_.bins.theta_binning == ThetaBinning::uniform) s << " (uniform theta)";
    if (bins_.theta_bins() < options_.bins.theta_bins)
      s << " (" << options_.bins.theta_bins << " theta bins requested, " << distinct_ << " distinct theta values)";
    if (neural_)
      s << ", neural, " << options_.iterations << " iterations, held-out KL " << std::setprecision(3) << held_out_kl_;
    else
      s << ", exact";
    s << ", " << asset_->file_size() << " bytes";
    return s.str();
  }

  NeuralHistogramBakeOptions options_;
  bool neural_ = true;
  HistogramBins bins_;
  uint64_t distinct_ = 0;
  double held_out_kl_ = 0.0;
};

}  // namespace

std::unique_ptr<Command> make_histogram_command() { return std::make_unique<HistogramCommand>(); }

}  // namespace mbk::cli
