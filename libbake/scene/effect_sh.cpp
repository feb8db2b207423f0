// The `sh` effect ([Han07] Sec. 7.4; libbake/filter/sh_pyramid.h): the material's normal map filtered as the
// spherical-harmonic coefficients of every MIP texel's normal distribution (asset kind `sh`, baked exactly as
// `microbake sh` does); its evaluator side is libbake/eval/sh_effect.h. Its keys are the `sh` technique's parameters
// (technique_parameters.cpp: order, precision, window), with the command's defaults and ranges.
#include "libbake/filter/sh_asset.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk {

EffectInfo sh_effect() {
  EffectInfo e;
  e.name = "sh";
  e.summary = "filtered normal-distribution shading from SH NDF pyramids ([Han07] Sec. 7.4; bakes sh)";
  e.parameters = effect_parameters("sh");
  e.assets = [](const Material& m, const EffectUse& use) {
    const BakeInput map = normal_map_input(m);
    const ShBakeOptions bake = sh_bake_options(use.options);
    // The parameters the asset records (sh_asset.h) that the options decide.
    const nlohmann::json parameters = {
        {"order", bake.order}, {"precision", precision_name(bake.precision)}, {"window", window_name(bake.window)}};
    return std::vector<AssetRecipe>{{"sh",
                                     parameters,
                                     {map},
                                     [map, bake](Progress& progress) {
                                       return bake_sh_asset(load_normal_map(map.path, map.normal_map->load_options()),
                                                            bake, progress);
                                     },
                                     use.options}};
  };
  return e;
}

}  // namespace mbk
