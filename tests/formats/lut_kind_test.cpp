// `validate` on kind 2, `lut` (formats/kind_lut.cpp): the hand-built fixture (tests/formats/lut_fixtures.h) is
// valid, and the slope check tolerates exactly float rounding: a stored slope one ulp off the exact slope passes,
// a few ulps off is reported (12007). One corrupt fixture per finding is in corrupt_fixtures_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(LutKind, SlopeCheckToleratesFloatRoundingOnly) {
  // forward_slope entry 2 of n_x is exactly 3 (samples 0 and 0.75, step 0.25).
  EXPECT_TRUE(error_ids(test::lut_with_value(2, 2, std::nextafter(3.0f, 4.0f))).empty());
  EXPECT_TRUE(error_ids(test::lut_with_value(2, 2, std::nextafter(3.0f, 2.0f))).empty());
  float off = 3.0f;
  for (int ulp = 0; ulp < 4; ++ulp) off = std::nextafter(off, 4.0f);
  EXPECT_EQ(error_ids(test::lut_with_value(2, 2, off)), std::vector<int>{12007});
}

}  // namespace
}  // namespace mbk
