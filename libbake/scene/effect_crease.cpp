// The `crease` effect ([Parilov05]; libbake/crease/crease_asset.h): the material's normal map reconstructed with
// crisp discontinuities along artist-drawn curves, optionally with a crease profile blended in by Eq. (1).
// Bakes one asset of kind `crease` from the normal map and the curves file; its evaluator side is
// libbake/eval/crease_effect.h. Keys: `curves` (required: the curves file, .json or .svg, libbake/crease/curve_set.h,
// relative to the scene file), the `crease` technique's parameters (technique_parameters.cpp: smooth_iterations,
// band) and `profile` (a crease profile object, libbake/crease/crease_profile_json.h; without one the map's own
// normals are read side-aware, b = 1 everywhere).
#include "libbake/crease/crease_asset.h"
#include "libbake/crease/crease_profile_json.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk {
namespace {

std::vector<Parameter> crease_parameters() {
  Parameter curves;
  curves.name = "curves";
  curves.type = ParameterType::file;
  curves.doc = "Discontinuity curves, .json or .svg, relative to the scene file";
  Parameter profile;
  profile.name = "profile";
  profile.type = ParameterType::object;
  profile.doc = "A crease profile blended in by [Parilov05] Eq. (1) (docs/SCENES.md \"Effect crease\")";
  std::vector<Parameter> parameters = effect_parameters("crease");
  parameters.insert(parameters.begin(), curves);
  parameters.push_back(profile);
  return parameters;
}

}  // namespace

EffectInfo crease_effect() {
  EffectInfo e;
  e.name = "crease";
  e.summary = "crisp creases along drawn curves at any magnification, with an optional profile (bakes crease)";
  e.parameters = crease_parameters();
  e.parse_options = [parameters = e.parameters](JsonObjectReader& r, const std::filesystem::path& folder) {
    EffectUse use;
    use.name = "crease";
    for (const Parameter& p : parameters) {
      if (p.type == ParameterType::file)
        use.options[p.name] = effect_file_option(r, p.name, folder, use);
      else if (p.type != ParameterType::object)
        use.options[p.name] = read_parameter(r, p);
      else if (const nlohmann::json* v = r.optional(p.name))
        use.options[p.name] = crease_profile_to_json(crease_profile_from_json(*v, r.child(p.name)));
    }
    return use;
  };
  e.assets = [](const Material& m, const EffectUse& use) {
    const BakeInput map = normal_map_input(m);
    const std::filesystem::path curves = use.files.at("curves");
    const CreaseBakeOptions options = crease_bake_options(use.options);
    std::vector<AssetRecipe> recipes{
        {"crease",
         {{"smooth_iterations", options.smooth_iterations}, {"band", options.band}},
         {map, {curves, std::nullopt, "--curves"}},
         [map, curves, options](Progress& progress) {
           const LoadedNormalMap loaded = load_normal_map(map.path, map.normal_map->load_options());
           const CurveSet set = load_curves(curves, loaded.map.width, loaded.map.height);
           return crease_asset_writer(bake_crease(std::move(loaded.map), set, options, progress), options,
                                      loaded.record, curves_record(curves, set));
         }}};
    recipes[0].technique_values = use.options;
    return recipes;
  };
  return e;
}

}  // namespace mbk
