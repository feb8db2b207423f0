// `validate` on kind 10, `lut` (formats/kind_lut.cpp): the hand-built fixture (tests/formats/lut_fixtures.h) is
// valid; knots must rise strictly in x and in z (a repeated x or z is reported, 20005); the retired kind 2 is
// refused with a note to rebake. One corrupt fixture per finding is in corrupt_fixtures_test.cpp.
#include <gtest/gtest.h>

#include "formats/validate.h"
#include "tests/formats/lut_fixtures.h"

namespace mbk {
namespace {

std::vector<int> error_ids(const std::vector<uint8_t>& bytes) {
  std::vector<int> ids;
  for (const Finding& f : validate_asset(bytes)) ids.push_back(f.id);
  return ids;
}

TEST(LutKind, HandBuiltFixtureHasNoFindings) { EXPECT_TRUE(error_ids(test::valid_lut_bytes()).empty()); }

TEST(LutKind, RepeatedKeysAreRefusedInBothAxes) {
  EXPECT_EQ(error_ids(test::lut_with_value(0, 4, -0.2f)), std::vector<int>{20005});  // x of knot 2 = knot 1's
  EXPECT_EQ(error_ids(test::lut_with_value(0, 5, -0.5f)), std::vector<int>{20005});  // z of knot 2 = knot 1's
  EXPECT_TRUE(error_ids(test::lut_with_value(0, 5, -0.4999f)).empty());
}

TEST(LutKind, RetiredKind2IsRefusedWithANoteToRebake) {
  std::vector<uint8_t> f = test::valid_lut_bytes();
  store_le<uint32_t>(&f[12], 2);
  test::reseal_header(f);
  const std::vector<Finding> findings = validate_asset(f);
  ASSERT_FALSE(findings.empty());
  EXPECT_EQ(findings.front().id, 2011);
  EXPECT_NE(findings.front().message.find("rebake"), std::string::npos) << findings.front().message;
}

}  // namespace
}  // namespace mbk
