// The `mip` asset: what bake_mip_asset writes passes validate_asset() with no findings (for odd and
// degenerate sizes too), holds the pyramid bit for bit, and records inputs, parameters, conventions and
// statistics; `microbake mip` writes the same through the CLI, and leaves no file behind on errors.
#include <gtest/gtest.h>

#include "formats/asset.h"
#include "formats/validate.h"
#include "libbake/core/hash.h"
#include "libbake/gen/generator.h"
#include "libbake/image/image_io.h"
#include "libbake/image/mip_asset.h"
#include "libbake/image/normal_map_encoding.h"
#include "tests/image/cli_run.h"

namespace mbk {
namespace {

LoadedNormalMap loaded(uint32_t w, uint32_t h) {
  LoadedNormalMap m;
  m.map = generate_bumps({w, h}, 3, Progress::silent());
  m.record.path = "in-memory.png";
  m.record.content_hash = "xxh3:0000000000000000";
  m.record.width = w, m.record.height = h, m.record.channels = 3;
  m.record.pixel_format = "uint16", m.record.convention = "+Y", m.record.invalid_policy = "error";
  return m;
}

class MipAssetSizes : public ::testing::TestWithParam<std::pair<uint32_t, uint32_t>> {};

TEST_P(MipAssetSizes, PassesValidationWithNoFindings) {
  const auto [w, h] = GetParam();
  const LoadedNormalMap input = loaded(w, h);
  const std::vector<uint8_t> bytes = bake_mip_asset(input).serialize();
  const std::vector<Finding> findings = validate_asset(bytes);
  for (const Finding& f : findings) ADD_FAILURE() << f.id << ": " << f.message;
  EXPECT_TRUE(findings.empty());

  const Asset a = Asset::parse(bytes, "mip");
  const NormalPyramid p = build_normal_pyramid(input.map);
  EXPECT_EQ(a.metadata()["parameters"]["levels"], p.levels.size());
  EXPECT_EQ(a.metadata()["parameters"]["width"], w);
  EXPECT_EQ(a.metadata()["parameters"]["height"], h);
  EXPECT_EQ(a.metadata()["inputs"][0], input.record.to_json());
  EXPECT_EQ(a.metadata()["conventions"]["normal_convention"], "+Y");
  for (size_t k = 0; k < p.levels.size(); ++k) {
    const std::vector<float> stored = a.read<float>("level_" + std::to_string(k));
    ASSERT_EQ(stored.size(), p.levels[k].texels.size() * 3);
    for (size_t i = 0; i < p.levels[k].texels.size(); ++i)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(stored[3 * i + c], p.levels[k].texels[i][c]);
  }
  const auto& mean = a.metadata()["statistics"]["mean_length"];
  ASSERT_EQ(mean.size(), p.levels.size());
  EXPECT_NEAR(mean[0].get<double>(), 1.0, 1e-6);
  for (size_t k = 0; k < mean.size(); ++k) {
    EXPECT_LE(mean[k].get<double>(), 1.0 + 1e-6);
    EXPECT_LE(a.metadata()["statistics"]["min_length"][k].get<double>(), mean[k].get<double>() + 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(OddAndDegenerate, MipAssetSizes,
                         ::testing::Values(std::pair{1u, 1u}, std::pair{5u, 3u}, std::pair{1u, 7u}, std::pair{64u, 64u},
                                           std::pair{100u, 37u}));

TEST(MipAsset, CliWritesAValidAssetRecordingTheInput) {
  test::ScratchDir dir;
  save_normal_map(dir / "in.png", generate_panels({48, 40}, 2, Progress::silent()), YConvention::minus_y);
  const auto run =
      test::run_cli("mip " + (dir / "in.png").string() + " --convention -Y -o " + (dir / "out.mbk").string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("6 levels"), std::string::npos) << run.out;
  const std::vector<uint8_t> bytes = test::file_bytes(dir / "out.mbk");
  EXPECT_TRUE(validate_asset(bytes).empty());
  const Asset a = Asset::parse(bytes, "out.mbk");
  const auto& in = a.metadata()["inputs"][0];
  EXPECT_EQ(in["convention"], "-Y");
  EXPECT_EQ(in["content_hash"], file_content_hash(dir / "in.png"));
  EXPECT_EQ(in["pixel_format"], "uint16");
  // Loaded as -Y, the map is the generator's +Y map again: level 0 matches it to 16-bit precision.
  const NormalMap truth = generate_panels({48, 40}, 2, Progress::silent());
  const std::vector<float> level0 = a.read<float>("level_0");
  double worst = 0;
  for (size_t i = 0; i < truth.texels.size(); ++i)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(level0[3 * i + c]) - truth.texels[i][c]));
  EXPECT_LT(worst, 1e-4);
  EXPECT_EQ(test::run_cli("validate " + (dir / "out.mbk").string(), dir).exit_code, 0);
}

TEST(MipAsset, CliIsDeterministicAcrossThreadCounts) {
  test::ScratchDir dir;
  save_normal_map(dir / "in.png", generate_leather({67, 45}, 4, Progress::silent()));
  ASSERT_EQ(
      test::run_cli("mip " + (dir / "in.png").string() + " --threads 1 -o " + (dir / "a.mbk").string(), dir).exit_code,
      0);
  ASSERT_EQ(test::run_cli("mip " + (dir / "in.png").string() + " --threads 2 -q -o " + (dir / "b.mbk").string(), dir)
                .exit_code,
            0);
  EXPECT_EQ(test::file_bytes(dir / "a.mbk"), test::file_bytes(dir / "b.mbk"));
}

TEST(MipAsset, CliErrorsLeaveNoOutput) {
  test::ScratchDir dir;
  const std::string out = (dir / "out.mbk").string();
  auto r = test::run_cli("mip " + (dir / "absent.png").string() + " -o " + out, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("microbake: error: "), std::string::npos);
  save_image(dir / "height.png", Image{2, 2, 1, {0.1f, 0.2f, 0.3f, 0.4f}}, {.png_bits = 8});
  r = test::run_cli("mip " + (dir / "height.png").string() + " -o " + out, dir);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("height map"), std::string::npos) << r.err;
  save_image(dir / "nan.exr", Image{1, 1, 3, {NAN, 0.0f, 1.0f}});
  r = test::run_cli("mip " + (dir / "nan.exr").string() + " -o " + out, dir);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("--repair-invalid"), std::string::npos) << r.err;
  r = test::run_cli("mip " + (dir / "nan.exr").string() + " --convention sideways -o " + out, dir);
  EXPECT_EQ(r.exit_code, 1);
  r = test::run_cli("mip " + (dir / "nan.exr").string() + " --frobnicate -o " + out, dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(out));
  for (const auto& e : std::filesystem::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().string().find(".partial"), std::string::npos) << e.path();
  // With --repair-invalid the same input bakes, and says so.
  r = test::run_cli("mip " + (dir / "nan.exr").string() + " --repair-invalid -o " + out, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1 invalid texel repaired"), std::string::npos) << r.out;
  EXPECT_EQ(Asset::open(out).metadata()["inputs"][0]["repaired_texels"], 1);
}

}  // namespace
}  // namespace mbk
