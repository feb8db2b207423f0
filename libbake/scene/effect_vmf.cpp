// The `vmf` effect ([Han07] Sec. 7.6, Alg. 7.1; libbake/filter/vmf_pyramid.h): the material's normal map filtered
// as a J-lobe von Mises-Fisher mixture per MIP texel (asset kind `vmf`, baked exactly as `microbake vmf` does);
// its evaluator side is libbake/eval/vmf_effect.h. Options (all optional, the command's with the same defaults):
//   lobes           4      J, 1..16
//   align           0      coherence weight C of Eq. (7.26), [0, 1e6]
//   tolerance       1e-6   EM stops when the mean log-likelihood per normal rises by less, [1e-15, 1]
//   max_iterations  1000   EM iterations at most per texel and start, [1, 100000]
// The command's --material (per-lobe features, Eq. 7.25) has no option here: the evaluator shades no features.
#include "libbake/filter/vmf_asset.h"
#include "libbake/scene/effect_registry.h"

namespace mbk {

EffectInfo vmf_effect() {
  EffectInfo e;
  e.name = "vmf";
  e.summary = "filtered normal-distribution shading from vMF mixture MIP maps ([Han07] Sec. 7.6; bakes vmf)";
  e.parse_options = [](JsonObjectReader& r, const std::filesystem::path&) {
    EffectUse use;
    use.name = "vmf";
    const VmfBakeOptions defaults;
    const nlohmann::json* v = r.optional("lobes");
    const uint32_t lobes = v ? json_uint(*v, r.child("lobes"), 1, kVmfMaxLobes) : uint32_t(defaults.lobes);
    v = r.optional("align");
    const double align = v ? json_number(*v, r.child("align"), 0.0, 1e6) : defaults.em.align;
    v = r.optional("tolerance");
    const double tolerance = v ? json_number(*v, r.child("tolerance"), 1e-15, 1.0) : defaults.em.tolerance;
    v = r.optional("max_iterations");
    const uint32_t max_iterations =
        v ? json_uint(*v, r.child("max_iterations"), 1, 100000) : uint32_t(defaults.em.max_iterations);
    use.options = {{"lobes", lobes}, {"align", align}, {"tolerance", tolerance}, {"max_iterations", max_iterations}};
    return use;
  };
  e.assets = [](const Material& m, const EffectUse& use) {
    const BakeInput map = normal_map_input(m);
    VmfBakeOptions bake;
    bake.lobes = use.options.at("lobes").get<int>();
    bake.em.align = use.options.at("align").get<double>();
    bake.em.tolerance = use.options.at("tolerance").get<double>();
    bake.em.max_iterations = use.options.at("max_iterations").get<int>();
    // The parameters the asset records (vmf_asset.h) that the options decide.
    const nlohmann::json parameters = {{"lobes", bake.lobes},
                                       {"align", bake.em.align},
                                       {"tolerance", bake.em.tolerance},
                                       {"max_iterations", bake.em.max_iterations},
                                       {"feature_channels", 0}};
    return std::vector<AssetRecipe>{
        {"vmf", parameters, {map}, [map, bake](Progress& progress) {
           const LoadedNormalMap input = load_normal_map(map.path, map.normal_map->load_options());
           return vmf_asset_writer(input, nullptr, build_vmf_pyramid(input.map, nullptr, bake, progress), bake);
         }}};
  };
  return e;
}

}  // namespace mbk
