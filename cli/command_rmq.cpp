// `microbake rmq INPUT -o OUT.mbk [--patch P] [--bits 16|8]`: bakes an example normal map's RMQ min/max table
// for glint range queries (asset kind `rmq`, libbake/glint/rmq_asset.h). Its summary line reports the wall
// time of loading, baking and writing (scripts/bench-glint-rmq.sh reads it; the asset holds no time).
#include <bit>
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "formats/error.h"
#include "formats/rmq_layout.h"
#include "libbake/glint/rmq_asset.h"
#include "libbake/glint/rmq_table.h"

namespace mbk::cli {
namespace {

class RmqCommand : public NormalMapBakingCommand {
 public:
  RmqCommand() : NormalMapBakingCommand("rmq", "RMQ table asset (.mbk)") {}

 private:
  void bake(Progress& progress) override {
    const uint32_t w = map().map.width, h = map().map.height;
    const nlohmann::json& given = parameters().at("patch");
    patch_ = given.is_null() ? rmq_default_patch(w, h) : given.get<uint32_t>();
    if (patch_ > std::min(w, h))
      throw Error(ExitCode::bad_command_line,
                  "--patch " + std::to_string(patch_) + " does not fit the " + map_size() + " example (at most " +
                      std::to_string(std::bit_floor(std::min(w, h))) + ")",
                  input().path);
    asset_ = bake_rmq_asset(map(), patch_, bits(), progress);
  }

  std::string summary() const override {
    const RmqLayout layout{map().map.width, map().map.height, patch_, rmq_levels_for_patch(patch_), bits()};
    std::ostringstream s;
    s << map_size() << ", patch " << patch_ << ", levels 0.." << layout.levels - 1 << ", " << bits() << " bits, table "
      << layout.table_bytes() << " bytes = " << std::fixed << std::setprecision(2)
      << double(layout.table_bytes()) / (1024.0 * 1024.0) << " MiB";
    return s.str();
  }

  uint32_t bits() const { return parameters().at("bits").get<uint32_t>(); }

  uint32_t patch_ = 0;
};

}  // namespace

std::unique_ptr<Command> make_rmq_command() { return std::make_unique<RmqCommand>(); }

}  // namespace mbk::cli
