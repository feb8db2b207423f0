// Scene options of the colour-map effects (libbake/scene/effect_colormap.cpp): defaults filled in, files resolved
// against the scene folder, the assets planned (the table always, the moment pyramid only for an image driver),
// and bad options refused with their JSON path.
#include <gtest/gtest.h>

#include "formats/error.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/scene.h"
#include "tests/scene/scene_test_fixtures.h"

namespace mbk {
namespace {

using nlohmann::json;

json scene_with(const json& effect) { return testing::one_material_scene({{"effects", {effect}}}); }

Error option_error(const json& effect) {
  try {
    parse_scene(scene_with(effect), "/scenes");
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << effect.dump();
  return Error(ExitCode::success, "");
}

TEST(ColormapEffectOptions, DefaultsAreFilledAndFilesResolved_NoNormalMapNeeded) {
  const Scene s = parse_scene(scene_with({{"name", "colormap"}, {"colormap", "maps/c.json"}}), "/scenes");
  const EffectUse& use = s.materials.at("m").effects.at(0);
  EXPECT_EQ(use.options["mode"], "filtered");
  EXPECT_EQ(use.options["table_size"], json({256, 256}));
  EXPECT_EQ(use.options["noise"]["cells"], json({8, 8}));
  EXPECT_EQ(use.options["scale"], 1.0);
  EXPECT_EQ(use.files.at("colormap"), std::filesystem::path("/scenes/maps/c.json"));
  // Noise driver: only the table is baked.
  const auto recipes = find_effect("colormap")->assets(s.materials.at("m"), use);
  ASSERT_EQ(recipes.size(), 1u);
  EXPECT_EQ(recipes[0].kind, "colormap");
  EXPECT_EQ(recipes[0].parameters, json({{"width", 256}, {"height", 256}}));
}

TEST(ColormapEffectOptions, ImageDriverAddsTheMomentPyramid) {
  const Scene s = parse_scene(scene_with({{"name", "colormap-height"},
                                          {"colormap", "c.png"},
                                          {"driver", "/abs/h.png"},
                                          {"sigma_max", 0.25},
                                          {"table_size", {64, 32}}}),
                              "/scenes");
  const EffectUse& use = s.materials.at("m").effects.at(0);
  EXPECT_EQ(use.options["sigma_h"], 0.1);
  EXPECT_FALSE(use.options.contains("noise"));
  const auto recipes = find_effect("colormap-height")->assets(s.materials.at("m"), use);
  ASSERT_EQ(recipes.size(), 2u);
  EXPECT_EQ(recipes[0].parameters, json({{"width", 64}, {"height", 32}, {"sigma_max", 0.25}}));
  EXPECT_EQ(recipes[1].kind, "moments");
  EXPECT_EQ(recipes[1].inputs.at(0).path, std::filesystem::path("/abs/h.png"));
}

TEST(ColormapEffectOptions, BadOptionsNameTheirPath) {
  struct Case {
    json effect;
    std::string where, fragment;
  };
  const std::string at = "materials.m.effects[0]";
  const std::vector<Case> cases = {
      {{{"name", "colormap"}}, at + ".colormap", "missing"},
      {{{"name", "colormap"}, {"colormap", ""}}, at + ".colormap", "empty"},
      {{{"name", "colormap"}, {"colormap", "c.json"}, {"mode", "smooth"}}, at + ".mode", "naive, filtered"},
      {{{"name", "colormap"}, {"colormap", "c.json"}, {"table_size", {1, 256}}}, at + ".table_size[0]", "outside"},
      {{{"name", "colormap"}, {"colormap", "c.json"}, {"table_size", 256}}, at + ".table_size", "[width, height]"},
      {{{"name", "colormap"}, {"colormap", "c.json"}, {"sigma_max", -1}}, at + ".sigma_max", "outside"},
      {{{"name", "colormap"}, {"colormap", "c.json"}, {"driver", "d.png"}, {"noise", json::object()}},
       at + ".noise",
       "not both"},
      {{{"name", "colormap"}, {"colormap", "c.json"}, {"noise", {{"octave", 3}}}}, at + ".noise.octave", "unknown"},
      {{{"name", "colormap"}, {"colormap", "c.json"}, {"noise", {{"octaves", 0}}}}, at + ".noise.octaves", "outside"},
      {{{"name", "colormap"}, {"colormap", "c.json"}, {"sigma_h", 0.1}}, at + ".sigma_h", "unknown"},
      {{{"name", "colormap-height"}, {"colormap", "c.json"}, {"sigma_h", 0}}, at + ".sigma_h", "outside"},
      {{{"name", "colormap-height"}, {"colormap", "c.json"}, {"slope_sigma", 0}}, at + ".slope_sigma", "outside"},
      {{{"name", "colormap-slope"}, {"colormap", "c.json"}, {"driver", "d.png"}}, at + ".driver", "unknown"},
      {{{"name", "colormap-slope"}, {"colormap", "c.json"}, {"direction_degrees", "x"}},
       at + ".direction_degrees",
       "number"},
  };
  for (const Case& c : cases) {
    const Error e = option_error(c.effect);
    EXPECT_EQ(e.code(), ExitCode::invalid_input) << c.effect.dump();
    EXPECT_EQ(e.where(), c.where) << c.effect.dump() << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(c.fragment), std::string::npos) << c.effect.dump() << ": " << e.what();
  }
}

}  // namespace
}  // namespace mbk
