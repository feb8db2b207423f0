// `microbake mip INPUT -o OUT.mbk`: bakes the MIP pyramid of a normal map (asset kind `mip`,
// libbake/image/mip_asset.h), the plain-filtering baseline the other techniques are compared with.
#include "cli/baking_command.h"
#include "formats/mip_levels.h"
#include "libbake/image/mip_asset.h"

namespace mbk::cli {
namespace {

class MipCommand : public NormalMapBakingCommand {
 public:
  MipCommand() : NormalMapBakingCommand("mip", "MIP pyramid asset (.mbk)") {}

 private:
  void bake(Progress&) override { asset_ = bake_mip_asset(take_map()); }

  std::string summary() const override {
    return map_size() + ", " + std::to_string(mip_level_sizes(map().map.width, map().map.height).size()) + " levels";
  }
};

}  // namespace

std::unique_ptr<Command> make_mip_command() { return std::make_unique<MipCommand>(); }

}  // namespace mbk::cli
