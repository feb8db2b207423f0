// parse_mip_parameters: the one reading of a `mip` asset's width/height/levels, shared by validate and the
// evaluator. Each refusal must say which key is wrong and how (missing, or the value it holds).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "formats/mip_levels.h"

namespace mbk {
namespace {

using nlohmann::json;

std::string problem_with(json parameters) {
  std::vector<LevelSize> sizes;
  return parse_mip_parameters(parameters, sizes);
}

TEST(MipParameters, ConsistentParametersGiveTheLevelSizes) {
  std::vector<LevelSize> sizes;
  EXPECT_EQ(parse_mip_parameters({{"width", 5}, {"height", 3}, {"levels", 3}}, sizes), "");
  ASSERT_EQ(sizes.size(), 3u);
  EXPECT_EQ(sizes[2].width, 1u);
  EXPECT_EQ(sizes[2].height, 1u);
  EXPECT_EQ(parse_mip_parameters({{"width", 4294967295u}, {"height", 1}, {"levels", 32}}, sizes), "");
}

TEST(MipParameters, MissingKeysAreNamedAsMissing) {
  EXPECT_EQ(problem_with({{"height", 3}, {"levels", 3}}), "parameters.width is missing");
  EXPECT_EQ(problem_with({{"width", 5}, {"levels", 3}}), "parameters.height is missing");
  EXPECT_EQ(problem_with({{"width", 5}, {"height", 3}}), "parameters.levels is missing");
  EXPECT_EQ(problem_with(json::array()), "parameters is [], not an object");
}

TEST(MipParameters, WrongValuesAreShownNotReportedMissing) {
  const std::string range = ", not an integer in 1..4294967295";
  EXPECT_EQ(problem_with({{"width", -4}, {"height", 3}, {"levels", 3}}), "parameters.width is -4" + range);
  EXPECT_EQ(problem_with({{"width", 0}, {"height", 3}, {"levels", 3}}), "parameters.width is 0" + range);
  EXPECT_EQ(problem_with({{"width", 5}, {"height", "3"}, {"levels", 3}}), "parameters.height is \"3\"" + range);
  EXPECT_EQ(problem_with({{"width", 5.0}, {"height", 3}, {"levels", 3}}), "parameters.width is 5.0" + range);
}

TEST(MipParameters, SidesAbove32BitsAreRefusedNotTruncated) {
  // 2^32 + 5 used to be read as 5, which made this a valid 5 x 3 pyramid.
  EXPECT_EQ(problem_with({{"width", 4294967301u}, {"height", 3}, {"levels", 3}}),
            "parameters.width is 4294967301, not an integer in 1..4294967295");
}

TEST(MipParameters, LevelsMustBeTheCountOfTheSize) {
  EXPECT_EQ(problem_with({{"width", 16}, {"height", 16}, {"levels", 3}}),
            "parameters.levels is 3, but a 16x16 pyramid has 5 levels");
  EXPECT_EQ(problem_with({{"width", 16}, {"height", 16}, {"levels", -1}}),
            "parameters.levels is -1, not an integer in 1..4294967295");
}

}  // namespace
}  // namespace mbk
