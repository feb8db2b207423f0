// `validate` on kind 6, `crease` (formats/kind_crease.cpp): the hand-built fixture (tests/formats/
// crease_fixtures.h) and a real bake are valid, and a baked asset reads back (read_crease_field) to exactly
// the baked field. One corrupt fixture per finding is in corrupt_fixtures_test.cpp.
#include <gtest/gtest.h>

#include "formats/asset.h"
#include "formats/validate.h"
#include "libbake/crease/crease_asset.h"
#include "tests/crease/crease_test_maps.h"
#include "tests/formats/crease_fixtures.h"

namespace mbk {
namespace {

std::vector<int> error_ids(const std::vector<uint8_t>& bytes) {
  std::vector<int> ids;
  for (const Finding& f : validate_asset(bytes)) ids.push_back(f.id);
  return ids;
}

TEST(CreaseKind, HandBuiltFixtureHasNoFindings) { EXPECT_TRUE(error_ids(test::crease_bytes()).empty()); }

TEST(CreaseKind, BakedAssetIsValidAndReadsBackExactly) {
  CurveSet curves;
  curves.curves.push_back({{{0.3, 0.2}, {12.7, 9.1}, {3.1, 9.8}}, true, "test"});
  curves.curves.push_back({{{6.5, 0.0}, {6.5, 10.0}}, false, "test"});  // along a lattice line
  const NormalMap map = test::map_from(13, 10, [](const Vec2& p) { return Vec3(0.1 * p.x(), -0.05 * p.y(), 1.0); });
  const BakedCrease baked = test::bake(map, curves);
  const std::vector<uint8_t> bytes =
      crease_asset_writer(BakedCrease(baked), {}, InputRecord{}, CurvesRecord{}).serialize();
  EXPECT_TRUE(error_ids(bytes).empty());
  const CreaseField f = read_crease_field(Asset::parse(bytes, "memory"));
  EXPECT_EQ(f.width, 13u);
  EXPECT_EQ(f.distance, baked.field.distance);
  EXPECT_EQ(f.gradient, baked.field.gradient);
  EXPECT_EQ(f.side, baked.field.side);
  EXPECT_EQ(f.crossing_h, baked.field.crossing_h);
  EXPECT_EQ(f.crossing_v, baked.field.crossing_v);
  EXPECT_EQ(f.segments, baked.field.segments);
  EXPECT_EQ(f.normals, baked.field.normals);
}

// Three curves ending at one point inside a cell make a junction record; it is valid and reads back exactly.
TEST(CreaseKind, JunctionRecordsAreValidAndReadBackExactly) {
  const BakedCrease baked =
      test::bake(test::flat_map(10, 10),
                 test::curves_of({{{4.3, 4.2}, {4.3, 0.0}}, {{4.3, 4.2}, {10.0, 4.2}}, {{0.0, 9.0}, {4.3, 4.2}}}));
  ASSERT_EQ(baked.field.junction_cells.size(), 1u);
  const std::vector<uint8_t> bytes =
      crease_asset_writer(BakedCrease(baked), {}, InputRecord{}, CurvesRecord{}).serialize();
  EXPECT_TRUE(error_ids(bytes).empty());
  const CreaseField f = read_crease_field(Asset::parse(bytes, "memory"));
  EXPECT_EQ(f.junction_cells, baked.field.junction_cells);
  EXPECT_EQ(f.junction_points, baked.field.junction_points);
  EXPECT_EQ(f.junction_spokes, baked.field.junction_spokes);
  EXPECT_EQ(f.segments, baked.field.segments);
}

}  // namespace
}  // namespace mbk
