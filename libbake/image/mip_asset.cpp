// Bakes the `mip` asset kind from a loaded normal map (see mip_asset.h).
#include "libbake/image/mip_asset.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mbk {
namespace {

// Per level: mean, minimum and maximum length of the stored mean normals.
nlohmann::json mip_statistics(const NormalPyramid& pyramid) {
  nlohmann::json mean = nlohmann::json::array(), min = nlohmann::json::array(), max = nlohmann::json::array();
  for (const NormalMap& level : pyramid.levels) {
    double sum = 0.0, lo = INFINITY, hi = 0.0;
    for (const Vec3f& n : level.texels) {
      const double len = n.cast<double>().norm();
      sum += len;
      lo = std::min(lo, len);
      hi = std::max(hi, len);
    }
    mean.push_back(sum / double(level.texels.size()));
    min.push_back(lo);
    max.push_back(hi);
  }
  return {{"mean_length", mean}, {"min_length", min}, {"max_length", max}};
}

}  // namespace

AssetWriter bake_mip_asset(LoadedNormalMap input) {
  const uint32_t width = input.map.width, height = input.map.height;
  NormalPyramid pyramid = build_normal_pyramid(std::move(input.map));
  if (pyramid.levels.empty()) throw Error(ExitCode::runtime_failure, "internal: empty normal map", input.record.path);
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({input.record.to_json()});
  metadata["parameters"] = {{"width", width}, {"height", height}, {"levels", uint32_t(pyramid.levels.size())}};
  metadata["conventions"] = normal_map_conventions();
  metadata["conventions"]["levels"] =
      "level k is max(1, floor(W / 2^k)) x max(1, floor(H / 2^k)); texel i covers [i W / w_k, (i+1) W / w_k) "
      "(likewise rows) and holds the unnormalised area-weighted mean of the finest normals over it";
  metadata["statistics"] = mip_statistics(pyramid);
  AssetWriter writer("mip", std::move(metadata));
  for (size_t k = 0; k < pyramid.levels.size(); ++k) {
    NormalMap& level = pyramid.levels[k];
    // Vec3f is three packed floats (no padding), so the texel array is the [h, w, 3] section as it is: the
    // writer takes it over.
    static_assert(sizeof(Vec3f) == 3 * sizeof(float));
    writer.add_bytes("level_" + std::to_string(k), ElementType::f32, {level.height, level.width, 3},
                     std::move(level.texels));
  }
  return writer;
}

}  // namespace mbk
