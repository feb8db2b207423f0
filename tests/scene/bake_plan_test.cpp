// Bake planning: each asset once however many materials share it, stable file names, default folder; and
// the skip/rebuild decisions of `bake` (asset_freshness.h) against real baked files.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include <xxhash.h>

#include "formats/asset.h"
#include "formats/atomic_file.h"
#include "tests/formats/asset_fixtures.h"
#include "formats/error.h"
#include "libbake/scene/asset_freshness.h"
#include "libbake/image/normal_map.h"
#include "libbake/scene/bake_plan.h"
#include "tests/scene/scene_test_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

using nlohmann::json;
using test::ScratchDir;

json map_material(const std::string& path, const json& effects, const std::string& convention = "+Y") {
  return {{"normal_map", {{"path", path}, {"convention", convention}}}, {"effects", effects}};
}

TEST(BakePlan, TwoMaterialsSharingAMapBakeOneAsset) {
  // "maps/../maps/a.png" names the same file as "maps/a.png"; the baselines of a and b are that same mip asset.
  const json materials = {{"a", map_material("maps/a.png", json::array({"mip"}))},
                          {"b", map_material("maps/../maps/a.png", json::array({"mip"}))},
                          {"c", map_material("maps/a.png", json::array())}};
  const Scene scene = parse_scene(testing::small_scene(materials), "/scenes");
  const auto plan = plan_assets(scene);
  ASSERT_EQ(plan.size(), 1u);
  EXPECT_EQ(plan[0].recipe.kind, "mip");
  EXPECT_EQ(plan[0].file_name, "");  // the map is not there to hash
  ASSERT_EQ(plan[0].uses.size(), 4u);
  EXPECT_EQ(plan[0].uses[0].material, "a");
  EXPECT_EQ(plan[0].uses[1].material, "b");
  EXPECT_EQ(plan[0].uses[2].effect, kBaselineUse);
  EXPECT_EQ(assets_for(plan, "b", "mip"), std::vector<const PlannedAsset*>{&plan[0]});
  EXPECT_EQ(assets_for(plan, "b", kBaselineUse), std::vector<const PlannedAsset*>{&plan[0]});
  EXPECT_TRUE(assets_for(plan, "c", "mip").empty());
  EXPECT_TRUE(assets_for(plan, "c", kBaselineUse).empty());  // no effect: shaded from the map itself
}

TEST(BakePlan, DifferentConventionOrMapIsADifferentAsset) {
  ScratchDir dir("plan_different");
  testing::write_bumpy_map(dir / "a.exr");
  testing::write_bumpy_map(dir / "c.exr", 24, 21);
  const json materials = {{"a", map_material("a.exr", json::array({"mip"}))},
                          {"b", map_material("a.exr", json::array({"mip"}), "-Y")},
                          {"c", map_material("c.exr", json::array({"mip"}))}};
  const auto plan = plan_assets(parse_scene(testing::small_scene(materials), dir.path()));
  ASSERT_EQ(plan.size(), 3u);
  EXPECT_NE(plan[0].file_name, plan[1].file_name);
  EXPECT_NE(plan[0].file_name, plan[2].file_name);
}

TEST(BakePlan, PlainMaterialsPlanNothing) {
  const json materials = {
      {"a", map_material("maps/a.png", json::array())}, {"b", json::object()}, {"c", json::object()}};
  EXPECT_TRUE(plan_assets(parse_scene(testing::small_scene(materials), "/scenes")).empty());
}

// The name is <stem>.<kind>.<XXH3-64 of the documented request text>.mbk, computed here from the text written out
// by hand: the inputs' content hashes, how each is read, the kind and the parameters, and nothing else.
TEST(BakePlan, FileNamesAreTheDocumentedContentAddress) {
  ScratchDir dir("plan_names");
  std::filesystem::create_directories(dir / "one/scenes");
  std::filesystem::create_directories(dir / "two/deeper/maps");
  testing::write_bumpy_map(dir / "one/bricks.v2.png.exr");
  std::filesystem::copy_file(dir / "one/bricks.v2.png.exr", dir / "two/deeper/maps/bricks.v2.png.exr");
  const json here_materials = {
      {"a", map_material("../bricks.v2.png.exr", json::array({{{"name", "sh"}, {"order", 3}}}))},
      {"b", json::object()},
      {"c", json::object()}};
  json there_materials = here_materials;
  there_materials["a"]["normal_map"]["path"] = (dir / "two/deeper/maps/bricks.v2.png.exr").string();
  const auto here = plan_assets(parse_scene(testing::small_scene(here_materials), dir / "one/scenes"));
  const auto there = plan_assets(parse_scene(testing::small_scene(there_materials), "/elsewhere"));
  ASSERT_EQ(here.size(), 2u);  // sh, and the baseline mip
  for (size_t i = 0; i < 2; ++i) EXPECT_EQ(here[i].file_name, there[i].file_name);
  const std::string hash = file_content_hash(dir / "one/bricks.v2.png.exr");
  const std::string text = R"({"inputs":[{"content_hash":")" + hash +
                           R"(","read_as":{"convention":"+Y","repair":false}}],"kind":"sh","parameters":)"
                           R"({"order":3,"precision":"f16","window":"none"}})";
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(XXH3_64bits(text.data(), text.size())));
  EXPECT_EQ(here[0].file_name, std::string("bricks_v2_png.sh.") + hex + ".mbk");
  EXPECT_TRUE(std::regex_match(here[1].file_name, std::regex(R"(bricks_v2_png\.mip\.[0-9a-f]{16}\.mbk)")))
      << here[1].file_name;
}

TEST(BakePlan, DefaultAssetFolderSitsBesideTheScene) {
  ScratchDir dir("plan_folder");
  testing::write_json(dir / "demo.json",
                      testing::small_scene({{"a", json::object()}, {"b", json::object()}, {"c", json::object()}}));
  EXPECT_EQ(default_asset_folder(load_scene(dir / "demo.json")), dir / "demo.assets");
}

class AssetFreshnessTest : public ::testing::Test {
 protected:
  ScratchDir dir{"freshness"};
  PlannedAsset planned_for(const std::string& convention = "+Y") {
    const json materials = {
        {"a", map_material("map.exr", json::array({"mip"}), convention)}, {"b", json::object()}, {"c", json::object()}};
    testing::write_json(dir / "s.json", testing::small_scene(materials));
    return plan_assets(load_scene(dir / "s.json")).at(0);
  }
  void bake(const PlannedAsset& a, const std::filesystem::path& file) { a.recipe.bake(Progress::silent()).write(file); }
  AssetFreshness check(const PlannedAsset& a, const std::filesystem::path& file) {
    return check_asset_freshness(a, file);
  }
};

TEST_F(AssetFreshnessTest, MissingThenUpToDateAfterBaking) {
  testing::write_bumpy_map(dir / "map.exr");
  const PlannedAsset a = planned_for();
  const auto file = dir / a.file_name;
  EXPECT_EQ(check(a, file).state, AssetState::missing);
  bake(a, file);
  const AssetFreshness f = check(a, file);
  EXPECT_EQ(f.state, AssetState::up_to_date) << f.reason;
}

TEST_F(AssetFreshnessTest, ChangedMapContentIsStale) {
  testing::write_bumpy_map(dir / "map.exr");
  const PlannedAsset a = planned_for();
  bake(a, dir / a.file_name);
  testing::write_bumpy_map(dir / "map.exr", 24, 21);
  const AssetFreshness f = check(a, dir / a.file_name);
  EXPECT_EQ(f.state, AssetState::stale);
  EXPECT_NE(f.reason.find("input map.exr changed"), std::string::npos) << f.reason;
}

TEST_F(AssetFreshnessTest, ChangedConventionIsStale) {
  testing::write_bumpy_map(dir / "map.exr");
  const PlannedAsset plus = planned_for("+Y");
  bake(plus, dir / "asset.mbk");
  const AssetFreshness f = check(planned_for("-Y"), dir / "asset.mbk");
  EXPECT_EQ(f.state, AssetState::stale);
  EXPECT_NE(f.reason.find("convention changed (recorded +Y, now -Y)"), std::string::npos) << f.reason;
}

TEST_F(AssetFreshnessTest, AutoIsTheDefaultAndItsDecisionKeepsTheAssetUpToDate) {
  testing::write_bumpy_map(dir / "map.exr");
  const json materials = {{"a", {{"normal_map", {{"path", "map.exr"}}}, {"effects", {"mip"}}}},
                          {"b", json::object()},
                          {"c", json::object()}};
  testing::write_json(dir / "s.json", testing::small_scene(materials));
  const PlannedAsset a = plan_assets(load_scene(dir / "s.json")).at(0);
  EXPECT_EQ(a.recipe.inputs.at(0).normal_map->convention, std::nullopt);
  bake(a, dir / a.file_name);
  // What auto decided is a function of the map's bytes, which the content hash already pins down.
  const AssetFreshness f = check(a, dir / a.file_name);
  EXPECT_EQ(f.state, AssetState::up_to_date) << f.reason;
  const nlohmann::json in = Asset::open(dir / a.file_name).metadata()["inputs"][0];
  EXPECT_EQ(in["convention_requested"], "auto");
  EXPECT_TRUE(in["convention_evidence"].contains("decision"));
  const AssetFreshness g = check(planned_for("+Y"), dir / a.file_name);
  EXPECT_EQ(g.state, AssetState::stale);
  EXPECT_NE(g.reason.find("convention changed (recorded auto, now +Y)"), std::string::npos) << g.reason;
}

TEST_F(AssetFreshnessTest, ChangedParameterIsStale) {
  testing::write_bumpy_map(dir / "map.exr");
  PlannedAsset a = planned_for();
  bake(a, dir / a.file_name);
  a.recipe.parameters = {{"levels", 2}};  // the baked file records the real level count of a 24x20 map: 5
  const AssetFreshness f = check(a, dir / a.file_name);
  EXPECT_EQ(f.state, AssetState::stale);
  EXPECT_NE(f.reason.find("parameter 'levels' changed"), std::string::npos) << f.reason;
  a.recipe.parameters = {{"levels", 5}};
  EXPECT_EQ(check(a, dir / a.file_name).state, AssetState::up_to_date);
}

TEST_F(AssetFreshnessTest, AssetFromAnotherMicrobakeVersionIsStale) {
  testing::write_bumpy_map(dir / "map.exr");
  const PlannedAsset a = planned_for();
  const auto file = dir / a.file_name;
  bake(a, file);
  std::vector<uint8_t> bytes = read_file_bytes(file);
  nlohmann::json meta = Asset::parse(bytes, "baked").metadata();
  meta["producer"]["version"] = "0.0.9";
  test::replace_metadata(bytes, meta.dump());  // same length, checksums resealed
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  const AssetFreshness f = check(a, file);
  EXPECT_EQ(f.state, AssetState::stale);
  EXPECT_NE(f.reason.find("baked by microbake 0.0.9"), std::string::npos) << f.reason;
}

TEST_F(AssetFreshnessTest, CorruptFileIsStale) {
  testing::write_bumpy_map(dir / "map.exr");
  const PlannedAsset a = planned_for();
  const auto file = dir / a.file_name;
  bake(a, file);
  std::filesystem::resize_file(file, std::filesystem::file_size(file) - 1);
  const AssetFreshness f = check(a, file);
  EXPECT_EQ(f.state, AssetState::stale);
  EXPECT_NE(f.reason.find("not a valid asset"), std::string::npos) << f.reason;
}

}  // namespace
}  // namespace mbk
