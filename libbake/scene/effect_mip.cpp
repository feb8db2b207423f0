// The `mip` effect: the material's normal map shipped as a baked MIP pyramid (asset kind `mip`,
// libbake/image/mip_asset.h); its evaluator side is libbake/eval/mip_effect.h. No options. The `toksvig` effect bakes
// the same asset (mip_asset_recipe), so a scene using both bakes it once.
#include "libbake/image/mip_asset.h"
#include "libbake/scene/effect_registry.h"

namespace mbk {

AssetRecipe mip_asset_recipe(const Material& m) {
  const BakeInput map = normal_map_input(m);
  return {"mip", nlohmann::json::object(), {map}, [map](Progress&) {
            return bake_mip_asset(load_normal_map(map.path, map.normal_map->load_options()));
          }};
}

EffectInfo mip_effect() {
  EffectInfo e;
  e.name = "mip";
  e.summary = "shade from the baked MIP pyramid of the normal map (the baseline, shipped as an asset)";
  e.assets = [](const Material& m, const EffectUse&) { return std::vector<AssetRecipe>{mip_asset_recipe(m)}; };
  return e;
}

}  // namespace mbk
