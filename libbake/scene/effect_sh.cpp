// The `sh` effect ([Han07] Sec. 7.4; libbake/filter/sh_pyramid.h): the material's normal map filtered as the
// spherical-harmonic coefficients of every MIP texel's normal distribution (asset kind `sh`, baked exactly as
// `microbake sh` does); its evaluator side is libbake/eval/sh_effect.h. Options (all optional, the command's
// with the same defaults):
//   order      8       highest SH band L, 0..256 ((L+1)^2 coefficients per texel)
//   precision  "f16"   f16 | f32, element type of the coefficient levels
//   window     "none"  none | hann | lanczos, per-band factors the evaluator applies against ringing
#include "libbake/core/sh_basis.h"
#include "libbake/filter/sh_asset.h"
#include "libbake/scene/effect_registry.h"

namespace mbk {

EffectInfo sh_effect() {
  EffectInfo e;
  e.name = "sh";
  e.summary = "filtered normal-distribution shading from SH NDF pyramids ([Han07] Sec. 7.4; bakes sh)";
  e.parse_options = [](JsonObjectReader& r, const std::filesystem::path&) {
    EffectUse use;
    use.name = "sh";
    const nlohmann::json* v = r.optional("order");
    const uint32_t order = v ? json_uint(*v, r.child("order"), 0, kMaxShOrder) : uint32_t(kShDefaultOrder);
    v = r.optional("precision");
    const std::string precision = v ? json_choice(*v, r.child("precision"), {"f16", "f32"}) : "f16";
    v = r.optional("window");
    const std::string window = v ? json_choice(*v, r.child("window"), {"none", "hann", "lanczos"}) : "none";
    use.options = {{"order", order}, {"precision", precision}, {"window", window}};
    return use;
  };
  e.assets = [](const Material& m, const EffectUse& use) {
    const BakeInput map = normal_map_input(m);
    const ShBakeOptions bake{use.options.at("order").get<int>(),
                             parse_precision(use.options.at("precision").get<std::string>()),
                             parse_window(use.options.at("window").get<std::string>())};
    // The parameters the asset records (sh_asset.h) that the options decide.
    const nlohmann::json parameters = {
        {"order", bake.order}, {"precision", precision_name(bake.precision)}, {"window", window_name(bake.window)}};
    return std::vector<AssetRecipe>{
        {"sh", parameters, {map}, [map, bake](Progress& progress) {
           const LoadedNormalMap input = load_normal_map(map.path, map.normal_map->load_options());
           return sh_asset_writer(input, build_sh_pyramid(input.map, bake.order, progress), bake);
         }}};
  };
  return e;
}

}  // namespace mbk
