// The `glints` effect ([Wang20]; libbake/glint/glint_technique.h): specular glints from the infinite,
// non-repeating microstructure blended from the material's normal map (the example). Bakes the example's
// standardization LUTs (asset kind `lut`), its RMQ table (asset kind `rmq`) and the map's `mip` asset, whose level 0
// is the example the evaluator blends (so rendering reads no source map); its evaluator side is
// libbake/eval/glints_effect.h. Keys (all optional; docs/SCENES.md "Effect glints"):
//   blending  "histogram"  none | linear | variance | histogram ([Wang20] Eqs. 4-6; none: one patch, for flakes)
//   sigma_r   0.01         intrinsic roughness, in normal units
//   patch     64           the rmq technique's --patch, at least 2 (target patches are half)
//   seed      1            patch placement hash seed
//   lut_size  4096         the lut technique's --size
//   bits      16           the rmq technique's --bits
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/rmq_asset.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk {
namespace {

std::vector<Parameter> glints_parameters() {
  Parameter blending;
  blending.name = "blending";
  blending.type = ParameterType::choice;
  blending.choices = {"none", "linear", "variance", "histogram"};
  blending.default_value = "histogram";
  blending.doc = "How patches blend: none (one patch, for flakes), linear, variance or histogram ([Wang20] Eqs. 4-6)";
  Parameter sigma_r;
  sigma_r.name = "sigma_r";
  sigma_r.type = ParameterType::number;
  sigma_r.min = 1e-6;
  sigma_r.max = 1.0;
  sigma_r.default_value = 0.01;
  sigma_r.doc = "Intrinsic roughness, in normal units";
  Parameter patch = effect_parameter("rmq", "patch", "patch");
  patch.min = 2;
  patch.default_value = 64;
  Parameter seed;
  seed.name = "seed";
  seed.min = 1;
  seed.max = 4294967295.0;
  seed.default_value = 1;
  seed.doc = "Patch placement hash seed";
  return {blending,
          sigma_r,
          patch,
          seed,
          effect_parameter("lut", "size", "lut_size"),
          effect_parameter("rmq", "bits", "bits")};
}

}  // namespace

EffectInfo glints_effect() {
  EffectInfo e;
  e.name = "glints";
  e.summary = "specular glints of an infinite microstructure blended from the normal map (bakes lut and rmq)";
  e.parameters = glints_parameters();
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
         },
         {{"size", lut_size}}},
        {"rmq",
         {{"patch", patch}, {"bits", bits}},
         {map},
         [map, patch, bits](Progress& progress) {
           return bake_rmq_asset(load_normal_map(map.path, map.normal_map->load_options()), patch, bits, progress);
         },
         {{"patch", patch}, {"bits", bits}}},
        mip_asset_recipe(m)};
  };
  return e;
}

}  // namespace mbk
