// `microbake compare IMAGE REFERENCE [--format text|json] [--max-rmse X] [--block N]`: error metrics of IMAGE against
// the REFERENCE (libbake/eval/image_difference.h: RMSE, relative MSE, PSNR with peak 1, relative L1 of block means).
// Exit 6 when --max-rmse is given and the RMSE is above it; images of different sizes are invalid input (3).
// --format json adds the load and comparison times (schema "microbake.compare/1", formats/schema/compare.schema.json).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>

#include "cli/command.h"
#include "cli/common_options.h"
#include "cli/parameter_options.h"
#include "cli/stage_timer.h"
#include "formats/error.h"
#include "libbake/eval/image_difference.h"
#include "libbake/image/image_io.h"
#include "libbake/image/normal_map.h"

namespace mbk::cli {
namespace {

class CompareCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("IMAGE", options_.a, "Image to assess (any format OpenImageIO reads)")->required();
    app.add_option("REFERENCE", options_.b, "Reference image, same size and channels")->required();
    add_format_option(app, options_.format);
    Parameter max_rmse;
    max_rmse.option = "--max-rmse";
    max_rmse.type = ParameterType::number;
    max_rmse.max = std::numeric_limits<double>::max();
    max_rmse.doc = "Exit 6 when the RMSE is above this";
    add_parameter_option(app, max_rmse, options_.max_rmse);
    add_parameter_option(app,
                         integer_option("--block", 1, 65536, 8,
                                        "Side in pixels of the blocks of the block_relative_l1 metric (sum |block mean "
                                        "IMAGE - block mean REFERENCE| / sum |block mean REFERENCE|)"),
                         options_.block);
  }

  int run() override {
    // Sizes come from the headers first, so that a file declaring a huge image is refused before it is decoded.
    for (const std::string& path : {options_.a, options_.b})
      (void)read_image_header_within(path, kMaxNormalMapSide, "image");
    StageTimer timer;
    ImageFileInfo info_a, info_b;
    const Image a = load_image(options_.a, &info_a), b = load_image(options_.b, &info_b);
    const double load_seconds = timer.lap();
    // An integer file (PNG) holds display-encoded values, a float file (EXR) linear radiance: their
    // difference would measure the tone curve, not the rendering.
    if (info_a.is_float != info_b.is_float)
      throw Error(ExitCode::invalid_input,
                  "cannot compare a display-encoded integer image with a linear float image (" + info_a.pixel_format +
                      " vs " + info_b.pixel_format + "): compare .exr with .exr or .png with .png",
                  options_.a + " vs " + options_.b);
    ImageDifference d;
    try {
      d = compare_images(a, b, options_.block);
    } catch (const Error& e) {
      throw Error(e.code(), e.what(), options_.a + " vs " + options_.b + (e.where().empty() ? "" : ", " + e.where()));
    }
    const double compare_seconds = timer.lap();
    const bool above = options_.max_rmse && d.rmse > *options_.max_rmse;
    if (options_.format == OutputFormat::json) {
      nlohmann::json j = {{"schema", "microbake.compare/1"},
                          {"a", options_.a},
                          {"b", options_.b},
                          {"width", a.width},
                          {"height", a.height},
                          {"channels", a.channels},
                          {"mse", d.mse},
                          {"rmse", d.rmse},
                          {"relative_mse", d.relative_mse},
                          {"psnr_db", std::isfinite(d.psnr_db) ? nlohmann::json(d.psnr_db) : nlohmann::json()},
                          {"psnr_peak", 1.0},
                          {"max_abs", d.max_abs},
                          {"block", d.block},
                          {"block_relative_l1",
                           std::isfinite(d.block_relative_l1) ? nlohmann::json(d.block_relative_l1) : nlohmann::json()},
                          {"max_rmse", options_.max_rmse ? nlohmann::json(*options_.max_rmse) : nlohmann::json()},
                          {"within_threshold", !above},
                          {"seconds", {{"load", load_seconds}, {"compare", compare_seconds}}}};
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf("A: %s\nB: %s (reference)\nsize: %ux%u, %u channels\n", options_.a.c_str(), options_.b.c_str(),
                  a.width, a.height, a.channels);
      std::printf("rmse:         %.6g\nrelative_mse: %.6g\n", d.rmse, d.relative_mse);
      if (std::isfinite(d.psnr_db))
        std::printf("psnr:         %.2f dB (peak 1)\n", d.psnr_db);
      else
        std::printf("psnr:         inf (identical)\n");
      std::printf("max_abs:      %.6g\n", d.max_abs);
      std::printf("block_l1:     %.6g (relative L1 of %ux%u block means)\n", d.block_relative_l1, d.block, d.block);
    }
    std::fflush(stdout);
    if (above) {
      char what[160];
      std::snprintf(what, sizeof what, "difference above threshold: RMSE %.6g > --max-rmse %.6g", d.rmse,
                    *options_.max_rmse);
      throw Error(ExitCode::difference_found, what, options_.a + " vs " + options_.b);
    }
    return 0;
  }

 private:
  struct Options {
    std::string a, b;
    OutputFormat format = OutputFormat::text;
    std::optional<double> max_rmse;
    uint32_t block = 8;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_compare_command() { return std::make_unique<CompareCommand>(); }

}  // namespace mbk::cli
