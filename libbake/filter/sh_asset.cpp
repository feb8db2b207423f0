// Writes the `sh` asset kind (see sh_asset.h).
#include "libbake/filter/sh_asset.h"

#include <Imath/half.h>

#include <cmath>
#include <numbers>

#include "formats/error.h"
#include "libbake/core/sh_basis.h"

namespace mbk {

std::string precision_name(ShPrecision p) { return p == ShPrecision::f16 ? "f16" : "f32"; }

ShPrecision parse_precision(const std::string& name) {
  if (name == "f16") return ShPrecision::f16;
  if (name == "f32") return ShPrecision::f32;
  throw Error(ExitCode::bad_command_line, "unknown precision '" + name + "' (expected f16 or f32)", "--precision");
}

AssetWriter sh_asset_writer(const LoadedNormalMap& input, const ShPyramid& pyramid, const ShBakeOptions& options) {
  const NormalMap& map = input.map;
  const int count = sh_count(pyramid.order);
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({input.record.to_json()});
  metadata["parameters"] = {{"width", map.width},
                            {"height", map.height},
                            {"levels", uint32_t(pyramid.levels.size() + 1)},
                            {"order", pyramid.order},
                            {"coefficients", count},
                            {"precision", precision_name(options.precision)},
                            {"window", window_name(options.window)}};
  metadata["conventions"] = normal_map_conventions();
  metadata["conventions"]["sh_basis"] =
      "real, orthonormal over the sphere, no Condon-Shortley phase, on tangent-space directions (x, y, z), theta "
      "from +z, phi = atan2(y, x); index k = l (l + 1) + m";
  metadata["conventions"]["levels"] =
      "level k is max(1, floor(W / 2^k)) x max(1, floor(H / 2^k)); texel i covers [i W / w_k, (i+1) W / w_k) (likewise "
      "rows); level 0 is stored as the normals (g_lm = Y_lm(n)), level k >= 1 as g_lm = area-weighted mean of "
      "Y_lm over the finest normals the texel covers";
  metadata["conventions"]["window"] = "evaluate sum_lm window[l] g_lm Y_lm; the stored g_lm are not windowed";
  nlohmann::json mean_length = nlohmann::json::array(), rounding = nlohmann::json::array();
  const double c1 = std::sqrt(3.0 / (4.0 * std::numbers::pi));
  std::vector<std::vector<Imath::half>> halves;
  for (const ShLevel& level : pyramid.levels) {
    double length_sum = 0.0, worst = 0.0;
    const size_t texels = size_t(level.width) * level.height;
    for (size_t t = 0; t < texels; ++t) {
      const float* g = &level.coefficients[t * size_t(count)];
      if (count > 3) length_sum += std::sqrt(double(g[1]) * g[1] + double(g[2]) * g[2] + double(g[3]) * g[3]) / c1;
    }
    if (options.precision == ShPrecision::f16) {
      std::vector<Imath::half> h(level.coefficients.size());
      for (size_t i = 0; i < h.size(); ++i) {
        h[i] = Imath::half(level.coefficients[i]);
        worst = std::max(worst, std::abs(double(float(h[i])) - double(level.coefficients[i])));
      }
      halves.push_back(std::move(h));
    }
    mean_length.push_back(count > 3 ? length_sum / double(texels) : 1.0);
    rounding.push_back(worst);
  }
  metadata["statistics"] = {{"mean_normal_length_per_level", mean_length}, {"max_rounding_error_per_level", rounding}};
  AssetWriter writer("sh", std::move(metadata));
  static_assert(sizeof(Vec3f) == 3 * sizeof(float));
  writer.add("normals", {map.height, map.width, 3},
             std::span<const float>(map.texels.front().data(), map.texels.size() * 3));
  for (size_t k = 0; k < pyramid.levels.size(); ++k) {
    const ShLevel& level = pyramid.levels[k];
    const std::vector<uint64_t> shape = {level.height, level.width, uint64_t(count)};
    if (options.precision == ShPrecision::f16)
      writer.add("level_" + std::to_string(k + 1), shape, halves[k]);
    else
      writer.add("level_" + std::to_string(k + 1), shape, level.coefficients);
  }
  std::vector<float> window;
  for (double w : window_factors(options.window, pyramid.order)) window.push_back(float(w));
  writer.add("window", {uint64_t(window.size())}, window);
  return writer;
}

}  // namespace mbk
