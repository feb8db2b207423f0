// `microbake histogram INPUT -o OUT.mbk [--method exact] [--theta-bins K] [--phi-bins N] [--theta-binning B]`: bakes a
// normal map's adaptive (or uniform) bins and the integral images of its per-bin counts, the exact binned P-NDF of any
// footprint (asset kind `histogram`, libbake/histogram/histogram_bake.h; [Shah24] Sec. 4.1, [GGN18]). The neural form
// ([Shah24] Sec. 4.2) is planned; --method accepts only exact until it lands.
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "libbake/histogram/histogram_asset.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk::cli {
namespace {

class HistogramCommand : public NormalMapBakingCommand {
 public:
  HistogramCommand() : NormalMapBakingCommand("histogram", "histogram asset (.mbk)") {}

 private:
  void bake(Progress& progress) override {
    options_ = histogram_bake_options(parameters());
    const uint64_t seed = histogram_seed(map().record.content_hash);
    BakedHistogram baked = bake_histogram(map().map, options_, seed, progress, input().path);
    bins_ = baked.bins;
    distinct_ = baked.theta.distinct_values;
    asset_ = histogram_asset_writer(map(), options_, seed, std::move(baked));
  }

  std::string summary() const override {
    std::ostringstream s;
    s << map_size() << ", " << bins_.theta_bins() << " x " << bins_.phi_bins << " bins";
    if (options_.theta_binning == ThetaBinning::uniform) s << " (uniform theta)";
    if (bins_.theta_bins() < options_.theta_bins)
      s << " (" << options_.theta_bins << " theta bins requested, " << distinct_ << " distinct theta values)";
    s << ", exact, " << asset_->file_size() << " bytes";
    return s.str();
  }

  HistogramBakeOptions options_;
  HistogramBins bins_;
  uint64_t distinct_ = 0;
};

}  // namespace

std::unique_ptr<Command> make_histogram_command() { return std::make_unique<HistogramCommand>(); }

}  // namespace mbk::cli
