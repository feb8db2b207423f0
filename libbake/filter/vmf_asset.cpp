// Writes the `vmf` asset kind (see vmf_asset.h).
#include "libbake/filter/vmf_asset.h"

namespace mbk {

AssetWriter vmf_asset_writer(const LoadedNormalMap& input, const nlohmann::json* material_record, VmfPyramid pyramid,
                             const VmfBakeOptions& options) {
  const NormalMap& map = input.map;
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({input.record.to_json()});
  if (material_record) metadata["inputs"].push_back(*material_record);
  metadata["parameters"] = {{"width", map.width},
                            {"height", map.height},
                            {"levels", uint32_t(pyramid.levels.size())},
                            {"lobes", pyramid.lobes},
                            {"align", options.em.align},
                            {"tolerance", options.em.tolerance},
                            {"max_iterations", options.em.max_iterations},
                            {"kappa_max", options.em.kappa_max},
                            {"feature_channels", pyramid.feature_count}};
  metadata["conventions"] = normal_map_conventions();
  metadata["conventions"]["lobes"] =
      "per lobe (alpha, alpha r_x, alpha r_y, alpha r_z) in tangent space; r is the lobe's mean resultant: "
      "kappa = A^-1(|r|) with A(k) = coth(k) - 1/k, capped at kappa_max, mu = r / |r|; alpha = 0 is an empty lobe; "
      "interpolate the four floats linearly, then r = (alpha r) / alpha";
  metadata["conventions"]["levels"] =
      "level k is max(1, floor(W / 2^k)) x max(1, floor(H / 2^k)); texel i covers [i W / w_k, (i+1) W / w_k) (likewise "
      "rows); level 0 holds one lobe (alpha 1, r = n) per texel, level k >= 1 an EM fit to the finest normals covered";
  if (pyramid.feature_count)
    metadata["conventions"]["features"] = "per lobe alpha y, y the responsibility-weighted mean of the material image";
  nlohmann::json iterations = nlohmann::json::array(), converged = nlohmann::json::array(),
                 ll = nlohmann::json::array(), empty = nlohmann::json::array(), reseeds = nlohmann::json::array();
  for (const VmfLevel& level : pyramid.levels) {
    iterations.push_back(level.statistics.mean_iterations);
    converged.push_back(level.statistics.converged_fraction);
    ll.push_back(level.statistics.mean_log_likelihood);
    empty.push_back(level.statistics.empty_lobe_fraction);
    reseeds.push_back(level.statistics.mean_reseeds);
  }
  metadata["statistics"] = {{"mean_em_iterations_per_level", iterations},
                            {"converged_fraction_per_level", converged},
                            {"mean_log_likelihood_per_level", ll},
                            {"empty_lobe_fraction_per_level", empty},
                            {"reseeded_lobes_per_texel_per_level", reseeds}};
  AssetWriter writer("vmf", std::move(metadata));
  const uint64_t J = uint64_t(pyramid.lobes), F = uint64_t(pyramid.feature_count);
  for (size_t k = 0; k < pyramid.levels.size(); ++k) {  // the levels' data moved in, not copied: no second pyramid
    VmfLevel& level = pyramid.levels[k];
    writer.add("level_" + std::to_string(k), {level.height, level.width, J, 4}, std::move(level.lobes));
    if (F) writer.add("features_" + std::to_string(k), {level.height, level.width, J, F}, std::move(level.features));
  }
  return writer;
}

}  // namespace mbk
