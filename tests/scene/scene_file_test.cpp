// Scene files: strict keys (every unknown key anywhere is rejected with its JSON path), typed values and
// ranges, defaults, and paths relative to the scene file's folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "formats/error.h"
#include "libbake/scene/json_fields.h"
#include "libbake/scene/scene.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A scene that uses every key the format has.
json full_scene() {
  return json::parse(R"({
    "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40, "width": 32, "height": 24},
    "shapes": [
      {"type": "plane", "center": [0, 0, 0], "normal": [0, 1, 0], "tangent": [1, 0, 0], "size": [4, 3],
       "uv_scale": [2, 2], "material": "brick"},
      {"type": "sphere", "center": [0, 1, 0], "normal": [0, 1, 0], "tangent": [1, 0, 0], "radius": 1,
       "uv_scale": [1, 1], "material": "plain"},
      {"type": "bent_quad", "center": [1, 1, 0], "normal": [0, 0, 1], "tangent": [1, 0, 0], "size": [2, 1],
       "angle": 90, "uv_scale": [1, 1], "material": "brick"}
    ],
    "materials": {
      "brick": {"albedo": [0.5, 0.4, 0.3],
                "specular": {"distribution": "beckmann", "roughness": 0.3, "f0": [0.04, 0.04, 0.04]},
                "normal_map": {"path": "maps/brick.png", "convention": "-Y", "repair": true},
                "effects": ["mip"]},
      "plain": {"albedo": 0.8}
    },
    "lights": [
      {"type": "point", "position": [1, 2, 3], "intensity": [10, 10, 10]},
      {"type": "directional", "direction": [0, -1, 0], "irradiance": 2},
      {"type": "environment", "path": "env/sky.exr", "scale": 0.5},
      {"type": "sky", "radiance": [0.1, 0.2, 0.3]}
    ]
  })");
}

// The Error parse_scene throws for `scene` (fails the test when none).
Error parse_error(const json& scene) {
  try {
    parse_scene(scene, "/scenes");
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << scene.dump();
  return Error(ExitCode::success, "");
}

// Visits every object in the JSON tree with its path in the scene format's notation.
void for_each_object(json& node, const std::string& path, const std::function<void(json&, const std::string&)>& visit) {
  if (node.is_object()) {
    visit(node, path);
    for (auto it = node.begin(); it != node.end(); ++it)
      for_each_object(it.value(), json_child_path(path, it.key()), visit);
  } else if (node.is_array()) {
    for (size_t i = 0; i < node.size(); ++i) for_each_object(node[i], json_index_path(path, i), visit);
  }
}

TEST(SceneFile, FullSceneParsesWithEveryValue) {
  const Scene s = parse_scene(full_scene(), "/scenes");
  EXPECT_EQ(s.camera.width, 32u);
  EXPECT_DOUBLE_EQ(s.camera.fov_y_degrees, 40);
  ASSERT_EQ(s.shapes.size(), 3u);
  EXPECT_EQ(s.shapes[2].type, ShapeType::bent_quad);
  EXPECT_DOUBLE_EQ(s.shapes[2].angle_degrees, 90);
  const Material& brick = s.materials.at("brick");
  EXPECT_EQ(brick.distribution, Distribution::beckmann);
  EXPECT_DOUBLE_EQ(brick.roughness, 0.3);
  ASSERT_TRUE(brick.normal_map);
  EXPECT_EQ(brick.normal_map->convention, YConvention::minus_y);
  EXPECT_TRUE(brick.normal_map->repair);
  ASSERT_EQ(brick.effects.size(), 1u);
  EXPECT_EQ(brick.effects[0].name, "mip");
  EXPECT_EQ(brick.effects[0].options, json::object());
  EXPECT_EQ(s.materials.at("plain").albedo, Vec3::Constant(0.8));
  EXPECT_EQ(s.lights.points.size(), 1u);
  EXPECT_EQ(s.lights.directionals[0].irradiance, Vec3::Constant(2));
  EXPECT_DOUBLE_EQ(s.lights.environments[0].scale, 0.5);
  EXPECT_EQ(s.lights.skies[0].radiance, Vec3(0.1, 0.2, 0.3));
}

TEST(SceneFile, ConventionNamesAreTheCommandLines) {
  for (const auto& [name, expected] :
       std::vector<std::pair<std::string, ConventionRequest>>{{"DirectX", YConvention::minus_y},
                                                              {"-y", YConvention::minus_y},
                                                              {"OpenGL", YConvention::plus_y},
                                                              {"Auto", std::nullopt}}) {
    json j = full_scene();
    j["materials"]["brick"]["normal_map"]["convention"] = name;
    EXPECT_EQ(parse_scene(j, "/scenes").materials.at("brick").normal_map->convention, expected) << name;
  }
  // auto is the default.
  json j = full_scene();
  j["materials"]["brick"]["normal_map"].erase("convention");
  EXPECT_EQ(parse_scene(j, "/scenes").materials.at("brick").normal_map->convention, std::nullopt);
}

TEST(SceneFile, EffectMayBeAnObjectWithItsName) {
  json j = full_scene();
  j["materials"]["brick"]["effects"] = json::array({{{"name", "mip"}}});
  const Scene scene = parse_scene(j, "/scenes");
  const Material& m = scene.materials.at("brick");
  ASSERT_EQ(m.effects.size(), 1u);
  EXPECT_EQ(m.effects[0].name, "mip");
}

TEST(SceneFile, DefaultsApplyToOmittedKeys) {
  json j = full_scene();
  j["camera"].erase("up");
  j["camera"].erase("fov_y");
  j["materials"]["plain"] = json::object();
  j["shapes"][1] = {{"type", "sphere"}, {"radius", 2}, {"material", "plain"}};
  const Scene s = parse_scene(j, "/scenes");
  EXPECT_EQ(s.camera.up, Vec3::UnitY());
  EXPECT_DOUBLE_EQ(s.camera.fov_y_degrees, 45);
  const Material& m = s.materials.at("plain");
  EXPECT_EQ(m.albedo, Vec3::Constant(0.5));
  EXPECT_EQ(m.distribution, Distribution::ggx);
  EXPECT_DOUBLE_EQ(m.roughness, 0.5);
  EXPECT_EQ(m.f0, Vec3::Constant(0.04));
  EXPECT_FALSE(m.normal_map);
  EXPECT_TRUE(m.effects.empty());
  EXPECT_EQ(s.shapes[1].center, Vec3::Zero());
  EXPECT_EQ(s.shapes[1].normal, Vec3::UnitY());
  EXPECT_EQ(s.shapes[1].uv_scale, Vec2::Ones());
}

TEST(SceneFile, RejectsEveryUnknownKeyWithItsPath) {
  json scene = full_scene();
  std::vector<std::string> object_paths;
  for_each_object(scene, "", [&](json&, const std::string& path) { object_paths.push_back(path); });
  // top, camera, 3 shapes, materials, 2 materials, specular, normal_map, 4 lights
  ASSERT_EQ(object_paths.size(), 14u);
  for (const std::string& path : object_paths) {
    json mutated = full_scene();
    for_each_object(mutated, "", [&](json& node, const std::string& p) {
      if (p == path) node["zz_typo"] = 1;
    });
    const Error e = parse_error(mutated);
    EXPECT_EQ(e.code(), ExitCode::invalid_input) << path;
    EXPECT_EQ(e.where(), json_child_path(path, "zz_typo")) << "object at '" << path << "'";
    // The keys of "materials" are material names: a new one is a material, and 1 is not a valid one.
    const std::string expected = path == "materials" ? "expected an object" : "unknown key 'zz_typo'";
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(SceneFile, MisspelledMaterialKeyNamesItsPathAndTheKnownKeys) {
  json j = full_scene();
  j["materials"]["brick"]["rougness"] = 0.3;
  const Error e = parse_error(j);
  EXPECT_EQ(e.where(), "materials.brick.rougness");
  EXPECT_NE(std::string(e.what()).find("specular"), std::string::npos) << e.what();
}

struct BadValue {
  std::string pointer;  // JSON pointer to replace
  json value;
  std::string where;     // expected error path
  std::string fragment;  // expected in the message
};

TEST(SceneFile, RejectsWrongTypesAndRangesWithTheirPaths) {
  const std::vector<BadValue> cases = {
      {"/camera/width", 0, "camera.width", "outside"},
      {"/camera/width", "32", "camera.width", "integer"},
      {"/camera/height", 20000, "camera.height", "outside"},
      {"/camera/fov_y", 180, "camera.fov_y", "outside"},
      {"/camera/position", json::array({0, 1}), "camera.position", "3 numbers"},
      {"/camera/look_at", json::array({0, 1, 5}), "camera.look_at", "equals position"},
      {"/camera/up", json::array({0, -1, -5}), "camera.up", "parallel"},
      {"/shapes/0/type", "cube", "shapes[0].type", "plane, sphere, bent_quad"},
      {"/shapes/0/size", json::array({1, 0}), "shapes[0].size[1]", "outside"},
      {"/shapes/0/tangent", json::array({0, 2, 0}), "shapes[0].tangent", "parallel"},
      {"/shapes/0/normal", json::array({0, 0, 0}), "shapes[0].normal", "non-zero"},
      {"/shapes/0/material", "nope", "shapes[0].material", "brick, plain"},
      {"/shapes/1/radius", -1, "shapes[1].radius", "outside"},
      {"/shapes/2/angle", 0, "shapes[2].angle", "use a plane"},
      {"/shapes/2/angle", 400, "shapes[2].angle", "outside"},
      {"/materials/brick/albedo", json::array({0.5, 1.5, 0}), "materials.brick.albedo[1]", "outside"},
      {"/materials/brick/specular/roughness", 0, "materials.brick.specular.roughness", "outside"},
      {"/materials/brick/specular/distribution", "phong", "materials.brick.specular.distribution", "beckmann, ggx"},
      {"/materials/brick/normal_map/convention", "+Z", "materials.brick.normal_map.convention",
       "+Y/opengl or -Y/directx"},
      {"/materials/brick/normal_map/repair", "yes", "materials.brick.normal_map.repair", "true or false"},
      {"/materials/brick/effects", json::array({"sparkles"}), "materials.brick.effects[0]", "known effects: mip"},
      {"/materials/brick/effects", json::array({{{"name", "mip"}, {"levels", 3}}}), "materials.brick.effects[0].levels",
       "unknown key"},
      {"/materials/brick/effects", json::array({json::object()}), "materials.brick.effects[0].name", "missing"},
      {"/materials/brick/effects", json::array({json::array()}), "materials.brick.effects[0]", "string"},
      {"/materials/brick/effects", json::array({"mip", "mip"}), "materials.brick.effects[1]", "twice"},
      {"/materials/brick/effects", "mip", "materials.brick.effects", "array"},
      {"/materials/plain/effects", json::array({"mip"}), "materials.plain.effects[0]", "needs a normal_map"},
      {"/lights/0/type", "area", "lights[0].type", "point, directional, environment, sky"},
      {"/lights/0/intensity", -1, "lights[0].intensity", "outside"},
      {"/lights/1/direction", json::array({0, 0, 0}), "lights[1].direction", "non-zero"},
      {"/lights/2/path", "", "lights[2].path", "empty"},
      {"/lights", json::object(), "lights", "array"},
  };
  for (const BadValue& c : cases) {
    json j = full_scene();
    j[json::json_pointer(c.pointer)] = c.value;
    const Error e = parse_error(j);
    EXPECT_EQ(e.code(), ExitCode::invalid_input) << c.pointer;
    EXPECT_EQ(e.where(), c.where) << c.pointer << " = " << c.value.dump() << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(c.fragment), std::string::npos) << c.pointer << ": " << e.what();
  }
}

// parse_json_strict on `text`: the Error it throws, or a failure when it accepts.
Error strict_parse_error(const std::string& text) {
  try {
    parse_json_strict(text, "s.json");
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return Error(ExitCode::success, "");
}

TEST(SceneFile, DuplicateKeysAreRefusedWithTheirJsonPath) {
  struct Case {
    std::string text, where;
  };
  const std::vector<Case> cases = {
      {R"({"camera": {}, "camera": {}})", "s.json: camera"},
      {R"({"materials": {"brick": {"specular": {"roughness": 0.3, "roughness": 0.5}}}})",
       "s.json: materials.brick.specular.roughness"},
      {R"({"shapes": [{"type": "plane"}, {"radius": 1, "type": "sphere", "radius": 2}]})", "s.json: shapes[1].radius"},
      {R"({"a": [[1, 2], [3, {"k": 1, "k": 2}]]})", "s.json: a[1][1].k"},
  };
  for (const Case& c : cases) {
    const Error e = strict_parse_error(c.text);
    EXPECT_EQ(e.code(), ExitCode::invalid_input) << c.text;
    EXPECT_EQ(e.where(), c.where) << c.text;
    EXPECT_NE(std::string(e.what()).find("duplicate key"), std::string::npos) << e.what();
  }
  // The same key in different objects, or the same value twice, is fine.
  EXPECT_NO_THROW(parse_json_strict(R"({"a": {"k": 1}, "b": {"k": 1}, "c": [{"k": 1}, {"k": 1}]})", "s.json"));
}

TEST(SceneFile, NestingTooDeepIsRefusedWithThePathThroughArrays) {
  // An object holding an array whose second element opens 63 nested arrays: the 65th container is refused. Every
  // array on the way already holds the element being read; the innermost one does not yet.
  const Error e = strict_parse_error(R"({"a": [0, )" + std::string(63, '['));
  EXPECT_EQ(e.code(), ExitCode::invalid_input);
  std::string where = "s.json: a[1]";
  for (int i = 0; i < 62; ++i) where += "[0]";
  EXPECT_EQ(e.where(), where);
  EXPECT_NE(std::string(e.what()).find("nested more than 64 deep"), std::string::npos) << e.what();
  // 64 deep (62 arrays, an object, an array) is accepted, and its value is where it was written.
  const nlohmann::json ok =
      parse_json_strict(std::string(62, '[') + R"({"k": [1, 2]})" + std::string(62, ']'), "s.json");
  const nlohmann::json* inner = &ok;
  for (int i = 0; i < 62; ++i) inner = &(*inner)[0];
  EXPECT_EQ((*inner)["k"][1], 2);
  EXPECT_THROW(parse_json_strict(std::string(62, '[') + R"({"k": [[2]]})" + std::string(62, ']'), "s.json"), Error);
}

TEST(SceneFile, ParsedDocumentsEqualTheLibrarysOwnParse) {
  // The strict parser builds the same document as nlohmann's parser for every kind of value.
  const std::string text =
      R"({"n": null, "t": true, "f": false, "i": -3, "u": 18446744073709551615, "d": 2.5e-3, "s": "x\u00e9",
          "e": {}, "ea": [], "a": [[], [1, [2, {"k": [3]}]], {"m": {"n": {}}}], "o": {"p": [null, "q"]}})";
  EXPECT_EQ(parse_json_strict(text, "s.json"), nlohmann::json::parse(text));
  EXPECT_EQ(parse_json_strict("7", "s.json"), 7);
  EXPECT_EQ(parse_json_strict(R"("top")", "s.json"), "top");
}

TEST(SceneFile, DuplicateKeyInASceneFileNamesTheFileAndPath) {
  const test::ScratchDir dir;
  std::string text = full_scene().dump();
  text.insert(text.find("\"fov_y\""), "\"width\": 64, ");  // camera.width twice
  std::ofstream(dir / "dup.json") << text;
  try {
    load_scene(dir / "dup.json");
    ADD_FAILURE() << "accepted a duplicate key";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_EQ(e.where(), (dir / "dup.json").string() + ": camera.width");
  }
}

TEST(SceneFile, IntegerErrorsShowTheValueAndNeverWrap) {
  json j = full_scene();
  j["camera"]["width"] = 2.5;
  EXPECT_NE(std::string(parse_error(j).what()).find("expected an integer, found number 2.5"), std::string::npos);
  j["camera"]["width"] = "32";
  EXPECT_NE(std::string(parse_error(j).what()).find("found string \"32\""), std::string::npos);
  // Above INT64_MAX: read as int64_t it used to wrap to -1 ("value -1 is outside").
  j["camera"]["width"] = std::numeric_limits<uint64_t>::max();
  const std::string what = parse_error(j).what();
  EXPECT_NE(what.find("value 18446744073709551615 is outside"), std::string::npos) << what;
}

TEST(SceneFile, MissingRequiredKeysAreNamed) {
  for (const char* pointer : {"/camera", "/shapes", "/materials", "/lights", "/camera/width", "/shapes/1/radius",
                              "/shapes/0/material", "/materials/brick/normal_map/path", "/lights/3/radiance"}) {
    json j = full_scene();
    const json::json_pointer p(pointer);
    j[p.parent_pointer()].erase(p.back());
    const Error e = parse_error(j);
    EXPECT_NE(std::string(e.what()).find("missing key '" + p.back() + "'"), std::string::npos)
        << pointer << ": " << e.what();
  }
}

TEST(SceneFile, PathsAreRelativeToTheSceneFolder) {
  const test::ScratchDir scratch;
  const fs::path& dir = scratch.path();
  fs::create_directories(dir / "scenes");
  json j = full_scene();
  j["materials"]["brick"]["normal_map"]["path"] = "../maps/brick.png";
  j["lights"][2]["path"] = "/absolute/sky.exr";
  std::ofstream(dir / "scenes" / "s.json") << j.dump();
  const Scene s = load_scene(dir / "scenes" / "s.json");
  EXPECT_EQ(s.materials.at("brick").normal_map->path, (dir / "maps" / "brick.png").lexically_normal());
  EXPECT_EQ(s.materials.at("brick").normal_map->path_as_written, "../maps/brick.png");
  EXPECT_EQ(s.lights.environments[0].path, fs::path("/absolute/sky.exr"));
  EXPECT_EQ(s.folder, dir / "scenes");
}

TEST(SceneFile, FileErrorsCarryTheFileAndJsonPath) {
  const test::ScratchDir dir;
  try {
    load_scene(dir / "absent.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::io_failure);
  }
  std::ofstream(dir / "broken.json") << "{\"camera\": ";
  try {
    load_scene(dir / "broken.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(std::string(e.what()).find("malformed JSON"), std::string::npos);
  }
  json j = full_scene();
  j["camera"]["fov"] = 40;
  std::ofstream(dir / "typo.json") << j.dump();
  try {
    load_scene(dir / "typo.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), (dir / "typo.json").string() + ": camera.fov");
  }
  std::ofstream(dir / "array.json") << "[1, 2]";
  try {
    load_scene(dir / "array.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(std::string(e.what()).find("expected an object"), std::string::npos);
  }
}

}  // namespace
}  // namespace mbk
