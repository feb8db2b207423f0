// Crease profiles from JSON (libbake/crease/crease_profile_json.h): defaults, each kind, and errors by name.
#include <gtest/gtest.h>

#include "formats/error.h"
#include "libbake/crease/crease_profile_json.h"

namespace mbk {
namespace {

void expect_error(const nlohmann::json& j, const char* fragment, const char* where) {
  try {
    crease_profile_from_json(j, "scene.json: materials.m.crease");
    ADD_FAILURE() << "no error for " << j.dump();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(e.message().find(fragment), std::string::npos) << e.message();
    EXPECT_NE(e.message().find(where), std::string::npos) << e.message();
  }
}

TEST(CreaseProfileJson, Defaults) {
  const CreaseProfile p = crease_profile_from_json(nlohmann::json::object(), "x");
  EXPECT_EQ(p.kind, CreaseProfileKind::v);
  EXPECT_EQ(p.depth, 1.0);
  EXPECT_EQ(p.width, 2.0);
  EXPECT_EQ(p.blend_start, 0.0);
  EXPECT_EQ(p.blend_end, 2.0);
}

TEST(CreaseProfileJson, EachKind) {
  EXPECT_EQ(crease_profile_from_json({{"kind", "rounded"}}, "x").kind, CreaseProfileKind::rounded);
  EXPECT_EQ(crease_profile_from_json({{"kind", "step"}, {"depth", -0.5}}, "x").depth, -0.5);
  const CreaseProfile t = crease_profile_from_json({{"kind", "table"}, {"table", {0, 0.5, 0.6}}, {"width", 3}}, "x");
  EXPECT_EQ(t.table, (std::vector<double>{0, 0.5, 0.6}));
  EXPECT_EQ(t.blend_end, 3.0);
  EXPECT_EQ(crease_profile_from_json({{"blend_end", 0}}, "x").blend_end, 0.0);  // the map everywhere
}

TEST(CreaseProfileJson, UnknownKey) { expect_error({{"widht", 2}}, "unknown key 'widht'", "crease.widht"); }
TEST(CreaseProfileJson, UnknownKind) { expect_error({{"kind", "u"}}, "v, rounded, step, table", "crease.kind"); }
TEST(CreaseProfileJson, ZeroWidth) { expect_error({{"width", 0}}, "> 0", "crease.width"); }
TEST(CreaseProfileJson, BlendReversed) {
  expect_error({{"blend_start", 2}, {"blend_end", 1}}, "blend_start <= blend_end", "crease.blend_end");
}
TEST(CreaseProfileJson, TableTooShort) {
  expect_error({{"kind", "table"}, {"table", {1}}}, "at least two", "crease.table");
}
TEST(CreaseProfileJson, TableForAnotherKind) { expect_error({{"table", {0, 1}}}, "only kind table", "crease.table"); }
TEST(CreaseProfileJson, NotANumber) { expect_error({{"depth", "deep"}}, "finite number", "crease.depth"); }

}  // namespace
}  // namespace mbk
