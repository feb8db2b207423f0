// The `crease` effect ([Parilov05]; libbake/crease/crease_asset.h): the material's normal map reconstructed with
// crisp discontinuities along artist-drawn curves, optionally with a crease profile blended in by Eq. (1).
// Bakes one asset of kind `crease` from the normal map and the curves file; its evaluator side is
// libbake/eval/crease_effect.h. Options:
//   curves             (required)  discontinuity curves, .json or .svg (libbake/crease/curve_set.h), a path
//                                  relative to the scene file
//   smooth_iterations  10          constrained smoothing iterations of the gradient map, 0..10000
//   band               4           texels around the curves where the distance map is exact, (0, 1e6]
//   profile            (none)      a crease profile object (libbake/crease/crease_profile_json.h); without one
//                                  the map's own normals are read side-aware (b = 1 everywhere)
#include "libbake/crease/crease_asset.h"
#include "libbake/crease/crease_profile_json.h"
#include "libbake/scene/effect_registry.h"

namespace mbk {

EffectInfo crease_effect() {
  EffectInfo e;
  e.name = "crease";
  e.summary = "crisp creases along drawn curves at any magnification, with an optional profile (bakes crease)";
  e.parse_options = [](JsonObjectReader& r, const std::filesystem::path& folder) {
    EffectUse use;
    use.name = "crease";
    use.options["curves"] = effect_file_option(r, "curves", folder, use);
    const nlohmann::json* v = r.optional("smooth_iterations");
    use.options["smooth_iterations"] =
        v ? json_uint(*v, r.child("smooth_iterations"), 0, kCreaseMaxSmoothIterations) : kCreaseDefaultSmoothIterations;
    v = r.optional("band");
    use.options["band"] = v ? json_number(*v, r.child("band"), 1e-6, 1e6) : kCreaseDefaultBand;
    if ((v = r.optional("profile")))
      use.options["profile"] = crease_profile_to_json(crease_profile_from_json(*v, r.child("profile")));
    return use;
  };
  e.assets = [](const Material& m, const EffectUse& use) {
    const BakeInput map = normal_map_input(m);
    const std::filesystem::path curves = use.files.at("curves");
    CreaseBakeOptions options;
    options.smooth_iterations = use.options.at("smooth_iterations");
    options.band = use.options.at("band");
    return std::vector<AssetRecipe>{{"crease",
                                     {{"smooth_iterations", options.smooth_iterations}, {"band", options.band}},
                                     {map, {curves, std::nullopt}},
                                     [map, curves, options](Progress& progress) {
                                       const LoadedNormalMap loaded =
                                           load_normal_map(map.path, map.normal_map->load_options());
                                       const CurveSet set = load_curves(curves, loaded.map.width, loaded.map.height);
                                       return crease_asset_writer(bake_crease(loaded.map, set, options, progress),
                                                                  options, loaded.record, curves_record(curves, set));
                                     }}};
  };
  return e;
}

}  // namespace mbk
