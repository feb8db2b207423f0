// `microbake crease INPUT --curves FILE -o OUT.mbk [--smooth-iterations N] [--band B]`: bakes a normal map with
// discontinuity curves into asset kind `crease` ([Parilov05]; libbake/crease/crease_asset.h). Its summary
// line reports what the simplification did and the wall time of loading, baking and writing.
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "libbake/crease/crease_asset.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk::cli {
namespace {

class CreaseCommand : public NormalMapBakingCommand {
 public:
  CreaseCommand() : NormalMapBakingCommand("crease", "crease asset (.mbk)") {}

 private:
  void add_inputs(CLI::App& app) override {
    NormalMapBakingCommand::add_inputs(app);
    app.add_option("--curves", curves_path_,
                   "Discontinuity curves: .json ({\"curves\": [{\"points\": [[x, y], ...], \"closed\": false}]}) or "
                   ".svg (path with M L H V Z and m l h v z, polyline, polygon, line; viewBox mapped onto the map), "
                   "in texel coordinates x right, y down, the map spanning [0, W] x [0, H]")
        ->type_name("FILE")
        ->required();
  }

  void load() override {
    NormalMapBakingCommand::load();
    curves_ = load_curves(curves_path_, map().map.width, map().map.height);
    record_ = curves_record(curves_path_, curves_);
  }

  void bake(Progress& progress) override {
    options_ = crease_bake_options(parameters());
    baked_ = bake_crease(take_map().map, curves_, options_, progress);
    asset_ = crease_asset_writer(std::move(baked_), options_, map().record, record_);  // baked_ keeps its statistics
  }

  std::string summary() const override {
    const SimplifyStatistics& s = baked_.simplify;
    std::ostringstream line;
    line << map_size() << ", " << record_.curves << " curve" << (record_.curves == 1 ? "" : "s") << ", "
         << record_.segments << " segments -> " << baked_.network_segments << " cell segments in "
         << s.cells_with_segments << " cells, " << s.merged_edges << " merged crossings (max shift "
         << std::setprecision(3) << s.max_merge_shift << " texels), " << s.deleted_segments << " deleted, "
         << s.junction_cells << " junction cell" << (s.junction_cells == 1 ? "" : "s") << "; band " << options_.band
         << ", " << options_.smooth_iterations << " smoothing iterations";
    return line.str();
  }

  std::string curves_path_;
  CurveSet curves_;
  CurvesRecord record_;
  CreaseBakeOptions options_;
  BakedCrease baked_;
};

}  // namespace

std::unique_ptr<Command> make_crease_command() { return std::make_unique<CreaseCommand>(); }

}  // namespace mbk::cli
