// Writes the `sh` asset kind (see sh_asset.h).
#include "libbake/filter/sh_asset.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "formats/error.h"
#include "libbake/core/uninitialized_vector.h"
#include "libbake/core/sh_basis.h"

namespace mbk {

std::string precision_name(ShPrecision p) { return p == ShPrecision::f16 ? "f16" : "f32"; }

ShPrecision parse_precision(const std::string& name) {
  if (name == "f16") return ShPrecision::f16;
  if (name == "f32") return ShPrecision::f32;
  throw Error(ExitCode::bad_command_line, "unknown precision '" + name + "' (expected f16 or f32)", "--precision");
}

namespace {

// Stores each row in the asset's precision (Stored: float or Imath::half) and computes the statistics per row;
// the rows' partial statistics are added in row order afterwards, so they do not depend on the thread count.
template <typename Stored>
class StoredShLevels final : public ShRowSink {
 public:
  struct Level {
    LevelSize size;
    UninitializedVector<Stored> coefficients;  // every element is written by take_row
    std::vector<double> row_length, row_worst;
  };

  void start(const std::vector<LevelSize>& levels, int count) override {
    count_ = size_t(count);
    levels_.resize(levels.size());
    for (size_t k = 0; k < levels.size(); ++k) {
      levels_[k].size = levels[k];
      levels_[k].coefficients.resize(size_t(levels[k].width) * levels[k].height * count_);
      levels_[k].row_length.assign(levels[k].height, 0.0);
      levels_[k].row_worst.assign(levels[k].height, 0.0);
    }
  }

  void take_row(size_t k, uint32_t row, const float* g) override {
    static const double c1 = std::sqrt(3.0 / (4.0 * std::numbers::pi));
    Level& level = levels_[k - 1];
    const size_t n = size_t(level.size.width) * count_;
    double length = 0.0;
    if (count_ > 3)
      for (size_t i = 0; i < n; i += count_)
        length +=
            std::sqrt(double(g[i + 1]) * g[i + 1] + double(g[i + 2]) * g[i + 2] + double(g[i + 3]) * g[i + 3]) / c1;
    level.row_length[row] = length;
    Stored* out = &level.coefficients[size_t(row) * n];
    if constexpr (std::is_same_v<Stored, float>) {
      std::copy(g, g + n, out);
    } else {
      double worst = 0.0;
      for (size_t i = 0; i < n; ++i) {
        out[i] = Stored(g[i]);
        worst = std::max(worst, std::abs(double(float(out[i])) - double(g[i])));
      }
      level.row_worst[row] = worst;
    }
  }

  std::vector<Level>& levels() { return levels_; }

 private:
  size_t count_ = 0;
  std::vector<Level> levels_;
};

template <typename Stored>
AssetWriter write_sh_asset(LoadedNormalMap& input, const ShBakeOptions& options, Progress& progress) {
  NormalMap& map = input.map;
  StoredShLevels<Stored> stored;
  stream_sh_pyramid(map, options.order, stored, progress);
  const int count = sh_count(options.order);
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({input.record.to_json()});
  metadata["parameters"] = {{"width", map.width},
                            {"height", map.height},
                            {"levels", uint32_t(stored.levels().size() + 1)},
                            {"order", options.order},
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
  for (const auto& level : stored.levels()) {
    double length_sum = 0.0, worst = 0.0;
    for (uint32_t row = 0; row < level.size.height; ++row)
      length_sum += level.row_length[row], worst = std::max(worst, level.row_worst[row]);
    mean_length.push_back(count > 3 ? length_sum / (double(level.size.width) * level.size.height) : 1.0);
    rounding.push_back(worst);
  }
  metadata["statistics"] = {{"mean_normal_length_per_level", mean_length}, {"max_rounding_error_per_level", rounding}};
  AssetWriter writer("sh", std::move(metadata));
  static_assert(sizeof(Vec3f) == 3 * sizeof(float));
  // Vec3f is three packed floats: the texel array is the [H, W, 3] section as it is, taken over (not copied).
  writer.add_bytes("normals", ElementType::f32, {map.height, map.width, 3}, std::move(map.texels));
  for (size_t k = 0; k < stored.levels().size(); ++k) {
    auto& level = stored.levels()[k];
    writer.add("level_" + std::to_string(k + 1), {level.size.height, level.size.width, uint64_t(count)},
               std::move(level.coefficients));
  }
  std::vector<float> window;
  for (double w : window_factors(options.window, options.order)) window.push_back(float(w));
  writer.add("window", {uint64_t(window.size())}, window);
  return writer;
}

}  // namespace

AssetWriter bake_sh_asset(LoadedNormalMap input, const ShBakeOptions& options, Progress& progress) {
  return options.precision == ShPrecision::f16 ? write_sh_asset<Imath::half>(input, options, progress)
                                               : write_sh_asset<float>(input, options, progress);
}

}  // namespace mbk
