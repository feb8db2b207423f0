// `microbake vmf INPUT -o OUT.mbk [--lobes J] [--align C] [--material IMAGE] [--tolerance T] [--max-iterations N]`:
// bakes vMF mixture MIP maps of a normal map (asset kind `vmf`, libbake/filter/vmf_asset.h; [Han07] Sec. 7.6).
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "cli/baking_command.h"
#include "formats/error.h"
#include "libbake/filter/vmf_asset.h"
#include "libbake/image/image_io.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk::cli {
namespace {

class VmfCommand : public NormalMapBakingCommand {
 public:
  VmfCommand() : NormalMapBakingCommand("vmf", "vMF mixture asset (.mbk)") {}

 private:
  void add_inputs(CLI::App& app) override {
    NormalMapBakingCommand::add_inputs(app);
    app.add_option("--material", material_path_,
                   "Colour/material image of the map's size (1-4 channels) averaged per lobe ([Han07] Eq. 7.25)")
        ->type_name("FILE");
  }

  void load() override {
    NormalMapBakingCommand::load();
    if (material_path_.empty()) return;
    ImageFileInfo info;
    material_ = load_image(material_path_, &info);
    if (material_->channels > 4)
      throw Error(ExitCode::invalid_input,
                  "material image has " + std::to_string(material_->channels) + " channels (at most 4)",
                  material_path_);
    material_record_ = {{"path", material_path_},
                        {"content_hash", file_content_hash(material_path_)},
                        {"bytes", std::filesystem::file_size(material_path_)},
                        {"width", material_->width},
                        {"height", material_->height},
                        {"channels", material_->channels},
                        {"pixel_format", info.pixel_format},
                        {"role", "material"}};
  }

  void bake(Progress& progress) override {
    options_ = vmf_bake_options(parameters());
    const Image* material = material_ ? &*material_ : nullptr;
    VmfPyramid pyramid = build_vmf_pyramid(map().map, material, options_, progress);
    std::ostringstream s;
    s << std::setprecision(3) << map_size() << ", " << pyramid.levels.size() << " levels, " << pyramid.lobes
      << " lobes per texel, align " << options_.em.align;
    if (pyramid.feature_count) s << ", " << pyramid.feature_count << " feature channels";
    if (pyramid.levels.size() > 1) {
      double iterations = 0.0;
      for (size_t k = 1; k < pyramid.levels.size(); ++k) iterations += pyramid.levels[k].statistics.mean_iterations;
      s << ", mean EM iterations " << iterations / double(pyramid.levels.size() - 1);
    }
    summary_ = s.str();
    // The pyramid's levels move into the writer (no second copy of the asset's bytes in memory).
    asset_ = vmf_asset_writer(map(), material ? &material_record_ : nullptr, std::move(pyramid), options_);
  }

  std::string summary() const override { return summary_ + ", " + std::to_string(asset_->file_size()) + " bytes"; }

  std::string material_path_;
  std::optional<Image> material_;
  nlohmann::json material_record_;
  VmfBakeOptions options_;
  std::string summary_;  // what the bake found, without the file size
};

}  // namespace

std::unique_ptr<Command> make_vmf_command() { return std::make_unique<VmfCommand>(); }

}  // namespace mbk::cli
