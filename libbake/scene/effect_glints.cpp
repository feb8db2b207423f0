// The `glints` effect ([Wang20]; libbake/glint/glint_technique.h): specular glints from the infinite,
// non-repeating microstructure blended from the material's normal map (the example). Bakes ONLY the example's
// standardization LUTs (asset kind `lut`) and its RMQ table (asset kind `rmq`); its evaluator side is
// libbake/eval/glints_effect.h. Options (all optional):
//   blending  "histogram"  none | linear | variance | histogram ([Wang20] Eqs. 4-6; none: one patch, for flakes)
//   sigma_r   0.01         intrinsic roughness, in normal units, (0, 1]
//   patch     64           example patch side in texels, a power of two in [2, 4096] (target patches are half)
//   seed      1            patch placement hash seed, [1, 2^32 - 1]
//   lut_size  4096         samples per standardization table, [2, 65536]
//   bits      16           RMQ code bits, 8 or 16
#include <string>

#include "formats/error.h"

#include "libbake/glint/lut_asset.h"
#include "libbake/glint/rmq_asset.h"
#include "libbake/scene/effect_registry.h"

namespace mbk {

EffectInfo glints_effect() {
  EffectInfo e;
  e.name = "glints";
  e.summary = "specular glints of an infinite microstructure blended from the normal map (bakes lut and rmq)";
  e.parse_options = [](JsonObjectReader& r, const std::filesystem::path&) {
    EffectUse use;
    use.name = "glints";
    const nlohmann::json* v = r.optional("blending");
    const std::string blending =
        v ? json_choice(*v, r.child("blending"), {"none", "linear", "variance", "histogram"}) : "histogram";
    v = r.optional("sigma_r");
    const double sigma_r = v ? json_number(*v, r.child("sigma_r"), 1e-6, 1.0) : 0.01;
    v = r.optional("patch");
    const uint32_t patch = v ? json_uint(*v, r.child("patch"), 2, 4096) : 64;
    if ((patch & (patch - 1)) != 0)
      throw Error(ExitCode::invalid_input, "glints patch must be a power of two, got " + std::to_string(patch),
                  r.child("patch"));
    v = r.optional("seed");
    const uint32_t seed = v ? json_uint(*v, r.child("seed"), 1, UINT32_MAX) : 1;
    v = r.optional("lut_size");
    const uint32_t lut_size = v ? json_uint(*v, r.child("lut_size"), 2, 65536) : 4096;
    v = r.optional("bits");
    const uint32_t bits = v ? json_uint(*v, r.child("bits"), 8, 16) : 16;
    if (bits != 8 && bits != 16)
      throw Error(ExitCode::invalid_input, "glints bits must be 8 or 16, got " + std::to_string(bits), r.child("bits"));
    use.options = {{"blending", blending}, {"sigma_r", sigma_r},   {"patch", patch},
                   {"seed", seed},         {"lut_size", lut_size}, {"bits", bits}};
    return use;
  };
  e.assets = [](const Material& m, const EffectUse& use) {
    const BakeInput map = normal_map_input(m);
    const uint32_t lut_size = use.options.at("lut_size"), patch = use.options.at("patch"),
                   bits = use.options.at("bits");
    return std::vector<AssetRecipe>{
        {"lut",
         {{"size", lut_size}},
         {map},
         [map, lut_size](Progress& progress) {
           const LoadedNormalMap loaded = load_normal_map(map.path, map.normal_map->load_options());
           return lut_asset_writer(bake_standardization_lut(loaded.map, lut_size, progress), loaded.record);
         }},
        {"rmq", {{"patch", patch}, {"bits", bits}}, {map}, [map, patch, bits](Progress& progress) {
           return bake_rmq_asset(load_normal_map(map.path, map.normal_map->load_options()), patch, bits, progress);
         }}};
  };
  return e;
}

}  // namespace mbk
