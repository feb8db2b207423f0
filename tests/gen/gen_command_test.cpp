// `microbake gen` end to end: files are byte-identical for the same kind, seed and size whatever
// --threads is, differ with the seed, have the requested size and encoding (16-bit PNG, float EXR), load
// back as the generator's map, and bad command lines exit 1 without leaving a file.
#include <gtest/gtest.h>

#include "libbake/gen/generator.h"
#include "libbake/image/image_io.h"
#include "libbake/image/normal_map.h"
#include "tests/image/cli_run.h"

namespace mbk {
namespace {

std::string out(const test::ScratchDir& dir, const std::string& name) { return " -o " + (dir / name).string(); }

TEST(GenCommand, SameSeedGivesByteIdenticalFilesWhateverTheThreadCount) {
  test::ScratchDir dir;
  for (const GeneratorKind& k : generator_kinds())
    for (const char* ext : {".png", ".exr"}) {
      const std::string kind(k.name), a = kind + "_a" + ext, b = kind + "_b" + ext, c = kind + "_c" + ext;
      ASSERT_EQ(test::run_cli("gen " + kind + " --size 70x45 --seed 3 --threads 1" + out(dir, a), dir).exit_code, 0);
      ASSERT_EQ(test::run_cli("gen " + kind + " --size 70x45 --seed 3 --threads 2" + out(dir, b), dir).exit_code, 0);
      ASSERT_EQ(test::run_cli("gen " + kind + " --size 70x45 --seed 4" + out(dir, c), dir).exit_code, 0);
      EXPECT_EQ(test::file_bytes(dir / a), test::file_bytes(dir / b)) << a;
      EXPECT_NE(test::file_bytes(dir / a), test::file_bytes(dir / c)) << a;
    }
}

TEST(GenCommand, WritesTheRequestedSizeAndEncoding) {
  test::ScratchDir dir;
  auto r = test::run_cli("gen leather --size 300x120" + out(dir, "l.png"), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("300x120"), std::string::npos);
  ImageFileInfo info;
  const Image png = load_image(dir / "l.png", &info);
  EXPECT_EQ(png.width, 300u);
  EXPECT_EQ(png.height, 120u);
  EXPECT_EQ(png.channels, 3u);
  EXPECT_EQ(info.pixel_format, "uint16");
  ASSERT_EQ(test::run_cli("gen panels --size 33 -q" + out(dir, "p.exr"), dir).exit_code, 0);
  const Image exr = load_image(dir / "p.exr", &info);
  EXPECT_EQ(info.pixel_format, "float");
  EXPECT_EQ(exr.width, 33u);
  EXPECT_EQ(exr.height, 33u);
  // The EXR holds the generator's unit vectors exactly (default seed 1).
  const NormalMap truth = generate_panels({33, 33}, 1, Progress::silent());
  for (size_t i = 0; i < truth.texels.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(exr.pixels[3 * i + c], truth.texels[i][c]);
  // The default size is 512 x 512.
  ASSERT_EQ(test::run_cli("gen flakes -q" + out(dir, "f.png"), dir).exit_code, 0);
  EXPECT_EQ(read_image_header(dir / "f.png").width, 512u);
  // The PNG loads back as the generator's map to 16-bit precision.
  ASSERT_EQ(test::run_cli("gen scratches --size 40x24 --seed 9 -q" + out(dir, "s.png"), dir).exit_code, 0);
  const NormalMap loaded = load_normal_map(dir / "s.png", {}).map;
  const NormalMap expected = generate_scratches({40, 24}, 9, Progress::silent());
  for (size_t i = 0; i < expected.texels.size(); ++i) EXPECT_LT((loaded.texels[i] - expected.texels[i]).norm(), 1e-4f);
}

TEST(GenCommand, BadCommandLinesExitOneAndWriteNothing) {
  test::ScratchDir dir;
  auto r = test::run_cli("gen marble" + out(dir, "x.png"), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bumps, brushed, scratches, flakes, leather, panels"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.rfind("microbake: error: ", 0), 0u) << r.err;
  for (const char* size : {"0", "12x", "x12", "abc", "16385", "5x-3", "3x4x5"})
    EXPECT_EQ(test::run_cli(std::string("gen bumps --size ") + size + out(dir, "x.png"), dir).exit_code, 1) << size;
  EXPECT_EQ(test::run_cli("gen bumps --seed -1" + out(dir, "x.png"), dir).exit_code, 1);
  EXPECT_EQ(test::run_cli("gen bumps" + out(dir, "x.jpg"), dir).exit_code, 1);
  EXPECT_EQ(test::run_cli("gen bumps --frobnicate" + out(dir, "x.png"), dir).exit_code, 1);
  EXPECT_EQ(test::run_cli("gen bumps", dir).exit_code, 1);  // -o is required
  EXPECT_EQ(test::run_cli("gen bumps -o " + (dir / "no" / "folder" / "x.png").string(), dir).exit_code, 2);
  for (const auto& e : std::filesystem::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().rfind("cli_", 0), 0u) << "left behind: " << e.path();
}

TEST(GenCommand, HelpListsKindsAndOptions) {
  test::ScratchDir dir;
  const auto r = test::run_cli("gen --help", dir);
  EXPECT_EQ(r.exit_code, 0);
  for (const char* s : {"bumps", "panels", "--size", "--seed", "--threads", "-o"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}

}  // namespace
}  // namespace mbk
