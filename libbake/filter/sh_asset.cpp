// Writes the `sh` asset kind (see sh_asset.h).
#include "libbake/filter/sh_asset.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/core/sh_basis.h"

namespace mbk {

std::string precision_name(ShPrecision p) { return p == ShPrecision::f16 ? "f16" : "f32"; }

ShPrecision parse_precision(const std::string& name) {
  if (name == "f16") return ShPrecision::f16;
  if (name == "f32") return ShPrecision::f32;
  throw Error(ExitCode::bad_command_line, "unknown precision '" + name + "' (expected f16 or f32)", "--precision");
}

AssetWriter sh_asset_writer(const LoadedNormalMap& input, ShPyramid pyramid, const ShBakeOptions& options) {
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
  // Per level, in parallel over rows: the statistics (per-row partials, added in row order) and the f16 copy;
  // the f32 coefficients are handed to the writer (f32) or freed once converted (f16).
  std::vector<std::vector<Imath::half>> halves(pyramid.levels.size());
  for (size_t k = 0; k < pyramid.levels.size(); ++k) {
    ShLevel& level = pyramid.levels[k];
    const bool to_half = options.precision == ShPrecision::f16;
    if (to_half) halves[k].resize(level.coefficients.size());
    std::vector<double> row_length(level.height, 0.0), row_worst(level.height, 0.0);
    parallel_for(0, level.height, [&](int64_t row) {
      const size_t begin = size_t(row) * level.width * size_t(count), end = begin + size_t(level.width) * count;
      for (size_t i = begin; i < end; i += size_t(count)) {
        const float* g = &level.coefficients[i];
        if (count > 3)
          row_length[size_t(row)] += std::sqrt(double(g[1]) * g[1] + double(g[2]) * g[2] + double(g[3]) * g[3]) / c1;
      }
      if (!to_half) return;
      double worst = 0.0;
      for (size_t i = begin; i < end; ++i) {
        const Imath::half h(level.coefficients[i]);
        halves[k][i] = h;
        worst = std::max(worst, std::abs(double(float(h)) - double(level.coefficients[i])));
      }
      row_worst[size_t(row)] = worst;
    });
    double length_sum = 0.0, worst = 0.0;
    for (uint32_t row = 0; row < level.height; ++row)
      length_sum += row_length[row], worst = std::max(worst, row_worst[row]);
    if (to_half) std::vector<float>().swap(level.coefficients);
    mean_length.push_back(count > 3 ? length_sum / (double(level.width) * level.height) : 1.0);
    rounding.push_back(worst);
  }
  metadata["statistics"] = {{"mean_normal_length_per_level", mean_length}, {"max_rounding_error_per_level", rounding}};
  AssetWriter writer("sh", std::move(metadata));
  static_assert(sizeof(Vec3f) == 3 * sizeof(float));
  writer.add("normals", {map.height, map.width, 3},
             std::span<const float>(map.texels.front().data(), map.texels.size() * 3));
  for (size_t k = 0; k < pyramid.levels.size(); ++k) {
    ShLevel& level = pyramid.levels[k];
    const std::vector<uint64_t> shape = {level.height, level.width, uint64_t(count)};
    if (options.precision == ShPrecision::f16)
      writer.add("level_" + std::to_string(k + 1), shape, std::move(halves[k]));
    else
      writer.add("level_" + std::to_string(k + 1), shape, std::move(level.coefficients));
  }
  std::vector<float> window;
  for (double w : window_factors(options.window, pyramid.order)) window.push_back(float(w));
  writer.add("window", {uint64_t(window.size())}, window);
  return writer;
}

}  // namespace mbk
