// The `vmf` effect ([Han07] Sec. 7.6, Alg. 7.1; libbake/filter/vmf_pyramid.h): the material's normal map filtered
// as a J-lobe von Mises-Fisher mixture per MIP texel (asset kind `vmf`, baked exactly as `microbake vmf` does);
// its evaluator side is libbake/eval/vmf_effect.h. Its keys are the `vmf` technique's parameters
// (technique_parameters.cpp: lobes, align, tolerance, max_iterations), with the command's defaults and ranges.
// The command's --material (per-lobe features, Eq. 7.25) is an input, not a key: the evaluator shades no features.
#include "libbake/filter/vmf_asset.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk {

EffectInfo vmf_effect() {
  EffectInfo e;
  e.name = "vmf";
  e.summary = "filtered normal-distribution shading from vMF mixture MIP maps ([Han07] Sec. 7.6; bakes vmf)";
  e.parameters = effect_parameters("vmf");
  e.assets = [](const Material& m, const EffectUse& use) {
    const BakeInput map = normal_map_input(m);
    const VmfBakeOptions bake = vmf_bake_options(use.options);
    // The parameters the asset records (vmf_asset.h) that the options decide.
    const nlohmann::json parameters = {{"lobes", bake.lobes},
                                       {"align", bake.em.align},
                                       {"tolerance", bake.em.tolerance},
                                       {"max_iterations", bake.em.max_iterations},
                                       {"feature_channels", 0}};
    return std::vector<AssetRecipe>{
        {"vmf",
         parameters,
         {map},
         [map, bake](Progress& progress) {
           const LoadedNormalMap input = load_normal_map(map.path, map.normal_map->load_options());
           return vmf_asset_writer(input, nullptr, build_vmf_pyramid(input.map, nullptr, bake, progress), bake);
         },
         use.options}};
  };
  return e;
}

}  // namespace mbk
