// `microbake lut INPUT -o OUT.mbk [--size N]`: bakes the standardization knots of an example normal map for
// histogram-preserving blending of glints (asset kind `lut`, libbake/glint/lut_asset.h).
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "libbake/glint/lut_asset.h"

namespace mbk::cli {
namespace {

class LutCommand : public NormalMapBakingCommand {
 public:
  LutCommand() : NormalMapBakingCommand("lut", "standardization LUT asset (.mbk)") {}

 private:
  void bake(Progress& progress) override {
    lut_ = bake_standardization_lut(map().map, parameters().at("size").get<uint32_t>(), progress);
    asset_ = lut_asset_writer(lut_, map().record);
  }

  std::string summary() const override {
    const LutChannelStatistics &x = lut_.statistics[0], &y = lut_.statistics[1];
    std::ostringstream s;
    s << std::setprecision(3) << map_size() << ", grid " << parameters().at("size").get<uint32_t>() << ": " << x.knots
      << " + " << y.knots << " knots; max |G_T - G| n_x " << x.forward_error << ", n_y " << y.forward_error
      << "; max |G^-1_T - G^-1| n_x " << x.inverse_error << ", n_y " << y.inverse_error << "; clipped tail mass n_x "
      << x.clipped_tail_mass << ", n_y " << y.clipped_tail_mass;
    return s.str();
  }

  BakedLut lut_;
};

}  // namespace

std::unique_ptr<Command> make_lut_command() { return std::make_unique<LutCommand>(); }

}  // namespace mbk::cli
