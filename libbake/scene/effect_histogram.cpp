// The `histogram` effect ([Shah24]; libbake/histogram/): glints under every light, environment maps included, from
// the binned P-NDF of the material's normal map with a spatially varying intrinsic roughness. Bakes the map's
// histogram asset only (`microbake histogram`, its method and bins); the roughness (a constant, or a texture that
// the shader reads at shading time, so changing it needs no rebake) and the SH order of the distant lighting are the
// shader's. Its evaluator side is libbake/eval/histogram_effect.h. Keys (docs/SCENES.md "Effect histogram"):
//   method         "exact"  exact: the histogram technique's exact table; neural: its neural histogram (kind
//                           neural_histogram, trained); pyramid: the exact table, compressed by the shader to a MIP
//                           pyramid of histograms of the neural predictor's bytes (the non-neural baseline)
//   theta_bins     9        the histogram technique's --theta-bins
//   phi_bins       32       the histogram technique's --phi-bins
//   theta_binning  adaptive the histogram technique's --theta-binning (uniform: the baseline of [Shah24] Fig. 3)
//   features, iterations, batch, seed   the technique's neural training options (used by method neural; features
//                           also sizes the pyramid's budget)
//   roughness      0.05     intrinsic roughness sigma of every normal's lobe, radians, in [0.001, 1]
//   roughness_map  (none)   an image whose first channel is sigma, relative to the scene file (overrides roughness)
//   sh_order       20       SH order of the distant lighting the NDF is dotted with
#include "libbake/histogram/histogram_asset.h"
#include "libbake/histogram/neural_histogram_asset.h"
#include "libbake/histogram/roughness_lobe.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk {
namespace {

Parameter scene_key(Parameter p) {
  p.in_scenes = true;
  return p;
}

std::vector<Parameter> histogram_parameters() {
  Parameter roughness;
  roughness.name = "roughness";
  roughness.type = ParameterType::number;
  roughness.min = kMinLobeRoughness;
  roughness.max = 1.0;
  roughness.default_value = 0.05;
  roughness.doc = "Intrinsic roughness sigma of every normal's lobe ([Shah24] Eq. 2), in radians";
  Parameter roughness_map;
  roughness_map.name = "roughness_map";
  roughness_map.type = ParameterType::file;
  roughness_map.optional_file = true;
  roughness_map.doc = "An image whose first channel is sigma, relative to the scene file; overrides roughness";
  Parameter sh_order;
  sh_order.name = "sh_order";
  sh_order.min = 1;
  sh_order.max = 64;
  sh_order.default_value = 20;
  sh_order.doc = "SH order of the distant lighting the NDF is dotted with ([Shah24] Eq. 9)";
  // Scenes default to the exact table, which bakes in seconds up to 1024^2 (the command defaults to neural, which
  // trains for minutes whatever the map's size but scales to maps whose table would not fit).
  Parameter method;
  method.name = "method";
  method.type = ParameterType::choice;
  method.choices = {"exact", "neural", "pyramid"};
  method.default_value = "exact";
  method.doc =
      "The binned P-NDF the shader reads: exact (the histogram command's exact table), neural (its neural histogram, "
      "[Shah24] Sec. 4.2) or pyramid (the exact table compressed at load to a MIP pyramid of histograms of the "
      "neural predictor's bytes, [DLW*22]: the non-neural baseline)";
  return {method,
          scene_key(effect_parameter("histogram", "theta_bins", "theta_bins")),
          scene_key(effect_parameter("histogram", "phi_bins", "phi_bins")),
          scene_key(effect_parameter("histogram", "theta_binning", "theta_binning")),
          scene_key(effect_parameter("histogram", "features", "features")),
          scene_key(effect_parameter("histogram", "iterations", "iterations")),
          scene_key(effect_parameter("histogram", "batch", "batch")),
          scene_key(effect_parameter("histogram", "seed", "seed")),
          roughness,
          roughness_map,
          sh_order};
}

}  // namespace

EffectInfo histogram_effect() {
  EffectInfo e;
  e.name = "histogram";
  e.summary =
      "glints under every light with spatially varying roughness from binned P-NDFs ([Shah24]; bakes histogram)";
  e.parameters = histogram_parameters();
  e.parse_options = [parameters = e.parameters](JsonObjectReader& r, const std::filesystem::path& folder) {
    EffectUse use;
    use.name = "histogram";
    for (const Parameter& p : parameters) {
      if (!p.optional_file)
        use.options[p.name] = read_parameter(r, p);
      else if (r.optional(p.name))
        use.options[p.name] = effect_file_option(r, p.name, folder, use);
    }
    return use;
  };
  e.assets = [](const Material& m, const EffectUse& use) {
    const BakeInput map = normal_map_input(m);
    const HistogramBakeOptions options = histogram_bake_options(use.options);
    AssetRecipe recipe;
    recipe.inputs = {map};
    // pyramid reads the exact asset: the same file as method exact.
    const std::string method = use.options.at("method") == "neural" ? "neural" : "exact";
    recipe.parameters = {{"method", method},
                         {"theta_bins_requested", options.theta_bins},
                         {"phi_bins", options.phi_bins},
                         {"theta_binning", use.options.at("theta_binning")}};
    recipe.technique = "histogram";
    recipe.technique_values = {{"method", method},
                               {"theta_bins", options.theta_bins},
                               {"phi_bins", options.phi_bins},
                               {"theta_binning", use.options.at("theta_binning")}};
    if (method == "neural") {
      const NeuralHistogramBakeOptions neural = neural_histogram_bake_options(use.options);
      recipe.kind = "neural_histogram";
      for (const char* key : {"features", "iterations", "batch"})
        recipe.parameters[key] = recipe.technique_values[key] = use.options.at(key);
      recipe.parameters["training_seed"] = recipe.technique_values["seed"] = use.options.at("seed");
      recipe.bake = [map, neural](Progress& progress) {
        const LoadedNormalMap loaded = load_normal_map(map.path, map.normal_map->load_options());
        return bake_neural_histogram_asset(loaded, neural, progress, map.path.string());
      };
    } else {
      recipe.kind = "histogram";
      recipe.bake = [map, options](Progress& progress) {
        const LoadedNormalMap loaded = load_normal_map(map.path, map.normal_map->load_options());
        const uint64_t seed = histogram_seed(loaded.record.content_hash);
        return histogram_asset_writer(loaded, options, seed,
                                      bake_histogram(loaded.map, options, seed, progress, map.path.string()));
      };
    }
    return std::vector<AssetRecipe>{recipe};
  };
  return e;
}

}  // namespace mbk
