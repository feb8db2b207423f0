// `microbake colormap INPUT -o OUT.mbk [--size WxH] [--sigma-max S] [--encoding auto|srgb|linear]`: bakes a colour
// map (gradient image or JSON stops) convolved with Gaussians into a (mean, sigma) table ([Heitz13] Eq. 10; asset
// kind `colormap`, libbake/colormap/colormap_table.h).
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "libbake/colormap/colormap_source.h"
#include "libbake/colormap/colormap_table.h"

namespace mbk::cli {
namespace {

class ColormapCommand : public BakingCommand {
 public:
  ColormapCommand() : BakingCommand("colormap", "prefiltered colour-map asset (.mbk)") {}

 private:
  void add_inputs(CLI::App& app) override {
    app.add_option("INPUT", path_,
                   "Colour map: a gradient image (one row, or the middle row is used) or JSON colour stops (.json)")
        ->required();
  }

  void load() override {
    source_ = load_colormap_source(path_, parse_color_encoding(parameters().at("encoding").get<std::string>()));
  }

  void bake(Progress& progress) override {
    ColormapTableOptions table;
    table.width = parameters().at("table_size")[0];
    table.height = parameters().at("table_size")[1];
    table.sigma_max = parameters().at("sigma_max");
    table.mean_min = source_.domain_min;
    table.mean_max = source_.domain_max;
    baked_ = bake_colormap_table(source_.curve, table, progress);
    asset_ = colormap_asset_writer(baked_, source_.record, source_.encoding);
  }

  std::string summary() const override {
    const ColormapTable& t = baked_.table;
    const ColormapTableStatistics& s = baked_.statistics;
    std::ostringstream line;
    line << std::setprecision(3) << baked_.curve.knots.size() << " knots, " << source_.encoding << " -> linear; "
         << t.width << "x" << t.height << " table, mean " << t.mean_min << ".." << t.mean_max << ", sigma 0.."
         << t.sigma_max << "; lookup error max " << s.lookup_max_error << ", rms " << s.lookup_rms_error
         << "; naive C(mean) off by up to " << s.naive_max_error;
    return line.str();
  }

  std::string path_;
  LoadedColormap source_;
  BakedColormap baked_;
};

}  // namespace

std::unique_ptr<Command> make_colormap_command() { return std::make_unique<ColormapCommand>(); }

}  // namespace mbk::cli
