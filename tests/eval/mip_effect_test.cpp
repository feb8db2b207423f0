// The evaluator's reading of a `mip` asset (load_mip_asset): it shares validate's parameter rules
// (parse_mip_parameters), so an asset whose parameters lie is refused with the reason, not misread.
#include <gtest/gtest.h>

#include "formats/error.h"
#include "libbake/eval/mip_effect.h"
#include "tests/formats/asset_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

void expect_refused(const std::string& key, const nlohmann::json& value, const std::string& reason) {
  const test::ScratchDir dir;
  test::mip_writer(5, 3, 0, key, value).write(dir / "a.mbk");
  try {
    load_mip_asset(dir / "a.mbk");
    ADD_FAILURE() << "accepted parameters." << key << " = " << value;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(e.message().find(reason), std::string::npos) << e.message();
  }
}

TEST(MipEffect, LoadsTheWholePyramid) {
  const test::ScratchDir dir;
  test::mip_writer(5, 3).write(dir / "a.mbk");
  const NormalPyramid p = load_mip_asset(dir / "a.mbk");
  ASSERT_EQ(p.levels.size(), 3u);
  EXPECT_EQ(p.levels[0].width, 5u);
  EXPECT_EQ(p.levels[0].height, 3u);
}

TEST(MipEffect, RefusesLyingParametersWithTheReason) {
  expect_refused("levels", 2, "parameters.levels is 2, but a 5x3 pyramid has 3 levels");
  expect_refused("width", (uint64_t(1) << 32) + 5, "parameters.width is 4294967301, not an integer");
  expect_refused("width", -5, "parameters.width is -5, not an integer");
}

}  // namespace
}  // namespace mbk
