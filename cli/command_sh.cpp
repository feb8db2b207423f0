// `microbake sh INPUT -o OUT.mbk [--order L] [--precision f16|f32] [--window none|hann|lanczos]`: bakes the SH
// NDF pyramid of a normal map (asset kind `sh`, libbake/filter/sh_asset.h; [Han07] Sec. 7.4).
#include <sstream>

#include "cli/baking_command.h"
#include "formats/mip_levels.h"
#include "libbake/core/sh_basis.h"
#include "libbake/filter/sh_asset.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk::cli {
namespace {

class ShCommand : public NormalMapBakingCommand {
 public:
  ShCommand() : NormalMapBakingCommand("sh", "SH NDF pyramid asset (.mbk)") {}

 private:
  void bake(Progress& progress) override {
    options_ = sh_bake_options(parameters());
    levels_ = mip_level_sizes(map().map.width, map().map.height).size();
    asset_ = bake_sh_asset(take_map(), options_, progress);
  }

  std::string summary() const override {
    std::ostringstream s;
    s << map_size() << ", " << levels_ << " levels, order " << options_.order << ", " << sh_count(options_.order) << " "
      << precision_name(options_.precision) << " coefficients per texel, window " << window_name(options_.window)
      << ", " << asset_->file_size() << " bytes";
    return s.str();
  }

  ShBakeOptions options_;
  size_t levels_ = 0;
};

}  // namespace

std::unique_ptr<Command> make_sh_command() { return std::make_unique<ShCommand>(); }

}  // namespace mbk::cli
