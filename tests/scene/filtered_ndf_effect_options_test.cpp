// Scene options of the filtered-NDF effects (libbake/scene/effect_sh.cpp, effect_vmf.cpp, effect_toksvig.cpp):
// defaults are the commands' (`microbake sh`, `microbake vmf`), each effect plans exactly its asset with the
// parameters the asset records, toksvig shares the `mip` asset, and bad options are refused with their JSON path.
#include <gtest/gtest.h>

#include "formats/error.h"
#include "libbake/filter/sh_asset.h"
#include "libbake/filter/vmf_pyramid.h"
#include "libbake/scene/bake_plan.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/scene.h"
#include "tests/scene/scene_test_fixtures.h"

namespace mbk {
namespace {

using nlohmann::json;

json scene_with(const json& effects) {
  return testing::one_material_scene({{"normal_map", {{"path", "maps/n.png"}}}, {"effects", effects}});
}

std::vector<AssetRecipe> recipes_of(const json& effect) {
  const Scene s = parse_scene(scene_with(json::array({effect})), "/scenes");
  const Material& m = s.materials.at("m");
  return find_effect(m.effects.at(0).name)->assets(m, m.effects.at(0));
}

TEST(FilteredNdfEffectOptions, DefaultsAreTheCommandsAndEachBakesExactlyItsAsset) {
  const Scene s = parse_scene(scene_with({"sh", "vmf", "toksvig"}), "/scenes");
  const Material& m = s.materials.at("m");
  EXPECT_EQ(m.effects.at(0).options, (json{{"order", kShDefaultOrder}, {"precision", "f16"}, {"window", "none"}}));
  const VmfBakeOptions vmf;
  EXPECT_EQ(m.effects.at(1).options, (json{{"lobes", vmf.lobes},
                                           {"align", vmf.em.align},
                                           {"tolerance", vmf.em.tolerance},
                                           {"max_iterations", vmf.em.max_iterations}}));
  EXPECT_EQ(m.effects.at(2).options, json::object());
  std::vector<std::string> kinds;
  for (const PlannedAsset& a : plan_assets(s)) kinds.push_back(a.recipe.kind);
  EXPECT_EQ(kinds, (std::vector<std::string>{"sh", "vmf", "mip"}));

  const auto sh = recipes_of({{"name", "sh"}, {"order", 16}, {"precision", "f32"}, {"window", "hann"}});
  ASSERT_EQ(sh.size(), 1u);
  EXPECT_EQ(sh[0].kind, "sh");
  EXPECT_EQ(sh[0].parameters, (json{{"order", 16}, {"precision", "f32"}, {"window", "hann"}}));
  EXPECT_EQ(sh[0].inputs.at(0).path, std::filesystem::path("/scenes/maps/n.png"));
  const auto v = recipes_of({{"name", "vmf"}, {"lobes", 2}, {"align", 0.5}, {"max_iterations", 7}});
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].kind, "vmf");
  EXPECT_EQ(v[0].parameters, (json{{"lobes", 2},
                                   {"align", 0.5},
                                   {"tolerance", vmf.em.tolerance},
                                   {"max_iterations", 7},
                                   {"feature_channels", 0}}));
}

TEST(FilteredNdfEffectOptions, ToksvigSharesTheMipAsset) {
  const Scene s = parse_scene(scene_with({"mip", "toksvig"}), "/scenes");
  const std::vector<PlannedAsset> plan = plan_assets(s);
  ASSERT_EQ(plan.size(), 1u);
  EXPECT_EQ(plan[0].recipe.kind, "mip");
  EXPECT_EQ(plan[0].uses.size(), 3u);  // mip, toksvig and the baseline
}

TEST(FilteredNdfEffectOptions, BadOptionsNameTheirPath) {
  struct Case {
    json effect;
    std::string where, fragment;
  };
  const std::string at = "materials.m.effects[0]";
  const std::vector<Case> cases = {
      {{{"name", "sh"}, {"order", 257}}, at + ".order", "outside"},
      {{{"name", "sh"}, {"order", -1}}, at + ".order", ""},
      {{{"name", "sh"}, {"precision", "f64"}}, at + ".precision", "f16, f32"},
      {{{"name", "sh"}, {"window", "gauss"}}, at + ".window", "hann"},
      {{{"name", "sh"}, {"lobes", 2}}, at + ".lobes", "unknown"},
      {{{"name", "vmf"}, {"lobes", 0}}, at + ".lobes", "outside"},
      {{{"name", "vmf"}, {"lobes", 17}}, at + ".lobes", "outside"},
      {{{"name", "vmf"}, {"align", -1}}, at + ".align", "outside"},
      {{{"name", "vmf"}, {"tolerance", 0}}, at + ".tolerance", "outside"},
      {{{"name", "vmf"}, {"max_iterations", 0}}, at + ".max_iterations", "outside"},
      {{{"name", "vmf"}, {"max-iterations", 5}}, at + ".max-iterations", "unknown"},
      {{{"name", "toksvig"}, {"order", 2}}, at + ".order", "unknown"},
  };
  for (const Case& c : cases) {
    try {
      parse_scene(scene_with(json::array({c.effect})), "/scenes");
      ADD_FAILURE() << "accepted: " << c.effect.dump();
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::invalid_input) << c.effect.dump();
      EXPECT_EQ(e.where(), c.where) << c.effect.dump() << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(c.fragment), std::string::npos) << c.effect.dump() << ": " << e.what();
    }
  }
}

TEST(FilteredNdfEffectOptions, EffectsNeedANormalMap) {
  json scene = scene_with({"sh"});
  scene["materials"]["m"].erase("normal_map");
  for (const char* name : {"sh", "vmf", "toksvig"}) {
    scene["materials"]["m"]["effects"] = {name};
    EXPECT_THROW(parse_scene(scene, "/scenes"), Error) << name;
  }
}

}  // namespace
}  // namespace mbk
