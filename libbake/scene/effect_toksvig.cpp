// The `toksvig` effect ([Toksvig05]; a baseline [Han07] compares with): plain MIP-mapped normals whose
// shortened mean turns into extra roughness. It needs the unnormalised mean normal of every MIP texel, which is
// exactly what the `mip` asset stores (libbake/image/normal_pyramid.h: level k >= 1 holds the area-weighted mean
// of the finest unit normals, not renormalised; the evaluator renormalises only to shade), so it bakes the
// material's `mip` asset (shared with the `mip` effect: a scene using both bakes it once). Its evaluator side is
// libbake/eval/toksvig_effect.h. No options: the roughness is the material's.
#include "libbake/scene/effect_registry.h"

namespace mbk {

EffectInfo toksvig_effect() {
  EffectInfo e;
  e.name = "toksvig";
  e.summary = "MIP-mapped normals with Toksvig's roughening by the mean normal's length (bakes mip)";
  e.assets = [](const Material& m, const EffectUse&) { return std::vector<AssetRecipe>{mip_asset_recipe(m)}; };
  return e;
}

}  // namespace mbk
