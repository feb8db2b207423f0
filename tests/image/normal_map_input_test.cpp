// What load_normal_map refuses or repairs, and what it records about each input: invalid texels (count and
// first position, or the repair policy's result), one-channel height maps, the size limit, file errors,
// and the input record with its content hash.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "formats/error.h"
#include "libbake/image/image_io.h"
#include "libbake/image/normal_map.h"
#include "tests/image/cli_run.h"

namespace mbk {
namespace {

const NormalMapLoadOptions kStrict{YConvention::plus_y, InvalidTexelPolicy::error};
const NormalMapLoadOptions kRepair{YConvention::plus_y, InvalidTexelPolicy::repair};

Error load_error(const std::filesystem::path& p, const NormalMapLoadOptions& o = kStrict) {
  try {
    load_normal_map(p, o);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error loading " << p;
  return Error(ExitCode::success, "");
}

// A 5 x 3 float map, all (0, 0, 1) except three invalid texels: NaN at (3, 1), zero at (0, 2), and
// z < 0 at (4, 2). Row-major scan order puts (3, 1) first.
Image invalid_float_map() {
  Image im{5, 3, 3, {}};
  for (int i = 0; i < 15; ++i) im.pixels.insert(im.pixels.end(), {0.0f, 0.0f, 1.0f});
  im.at(3, 1, 0) = std::numeric_limits<float>::quiet_NaN();
  im.at(0, 2, 2) = 0.0f;
  im.at(4, 2, 0) = 0.6f, im.at(4, 2, 1) = 0.0f, im.at(4, 2, 2) = -0.8f;
  im.at(1, 0, 0) = 0.3f;  // valid, not unit: renormalised
  return im;
}

TEST(NormalMapInput, InvalidTexelsErrorNamesCountAndFirstPosition) {
  test::ScratchDir dir;
  save_image(dir / "bad.exr", invalid_float_map());
  const Error e = load_error(dir / "bad.exr");
  EXPECT_EQ(e.code(), ExitCode::invalid_input);
  const std::string what = e.what();
  EXPECT_NE(what.find("3 invalid texels"), std::string::npos) << what;
  EXPECT_NE(what.find("(x, row) = (3, 1)"), std::string::npos) << what;
  EXPECT_NE(what.find("NaN or Inf"), std::string::npos) << what;
  EXPECT_EQ(e.where(), (dir / "bad.exr").string());
}

TEST(NormalMapInput, FirstInvalidTexelReasonIsReported) {
  test::ScratchDir dir;
  Image im{2, 2, 3, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0}};  // zero vector at (1, 1)
  save_image(dir / "zero.exr", im);
  const std::string what = load_error(dir / "zero.exr").what();
  EXPECT_NE(what.find("1 invalid texel "), std::string::npos) << what;
  EXPECT_NE(what.find("(1, 1): zero length"), std::string::npos) << what;
  im.pixels = {0, 0, 1, 0.1f, 0.1f, -0.5f, 0, 0, 1, 0, 0, 1};
  save_image(dir / "below.exr", im);
  EXPECT_NE(std::string(load_error(dir / "below.exr").what()).find("(1, 0): z < 0"), std::string::npos);
}

TEST(NormalMapInput, RepairPolicyFixesAndCountsInvalidTexels) {
  test::ScratchDir dir;
  save_image(dir / "bad.exr", invalid_float_map());
  const LoadedNormalMap m = load_normal_map(dir / "bad.exr", kRepair);
  EXPECT_EQ(m.record.repaired_texels, 3u);
  EXPECT_EQ(m.record.invalid_policy, "repair");
  EXPECT_EQ(m.map.at(3, 1), Vec3f(0, 0, 1));                           // NaN -> (0, 0, 1)
  EXPECT_EQ(m.map.at(0, 2), Vec3f(0, 0, 1));                           // zero -> (0, 0, 1)
  EXPECT_NEAR((m.map.at(4, 2) - Vec3f(1, 0, 0)).norm(), 0.0f, 1e-7f);  // z < 0 -> horizon (0.6, 0, 0) normalised
  EXPECT_NEAR((m.map.at(1, 0).cast<double>() - Vec3(0.3, 0, 1).normalized()).norm(), 0.0, 1e-7);
  for (const Vec3f& n : m.map.texels) EXPECT_NEAR(n.norm(), 1.0f, 1e-6f);
}

TEST(NormalMapInput, RepairOfStraightDownGivesUp) {
  test::ScratchDir dir;
  save_image(dir / "down.exr", Image{1, 1, 3, {0, 0, -1}});
  EXPECT_EQ(load_normal_map(dir / "down.exr", kRepair).map.texels[0], Vec3f(0, 0, 1));  // horizon of (0,0,-1) is zero
}

TEST(NormalMapInput, ValidMapRecordsNoRepairs) {
  test::ScratchDir dir;
  save_image(dir / "ok.exr", Image{1, 1, 3, {0.1f, 0.2f, 0.9f}});
  EXPECT_EQ(load_normal_map(dir / "ok.exr", kRepair).record.repaired_texels, 0u);
  EXPECT_EQ(load_normal_map(dir / "ok.exr", kStrict).record.invalid_policy, "error");
}

TEST(NormalMapInput, IntegerHorizonCodeIsNotInvalid) {
  test::ScratchDir dir;
  // Blue 127 decodes to z = -1/255: the horizon rounded down, accepted as z = 0. Blue 126 is below it.
  save_image(dir / "h127.png", Image{1, 1, 3, {1.0f, float(128 / 255.0), float(127 / 255.0)}}, {.png_bits = 8});
  const LoadedNormalMap m = load_normal_map(dir / "h127.png", kStrict);
  EXPECT_EQ(m.map.texels[0].z(), 0.0f);
  EXPECT_NEAR(m.map.texels[0].x(), 1.0f, 1e-4f);
  save_image(dir / "h126.png", Image{1, 1, 3, {1.0f, float(128 / 255.0), float(126 / 255.0)}}, {.png_bits = 8});
  EXPECT_NE(std::string(load_error(dir / "h126.png").what()).find("z < 0"), std::string::npos);
  // The same tolerance in 16 bits is one 16-bit code: 32767 is the horizon, 32766 is not.
  save_image(dir / "h16.png", Image{1, 1, 3, {1.0f, 0.5f, float(32766 / 65535.0)}}, {.png_bits = 16});
  EXPECT_EQ(load_error(dir / "h16.png").code(), ExitCode::invalid_input);
  // Floats have no rounding to excuse: any z < 0 is invalid.
  save_image(dir / "hf.exr", Image{1, 1, 3, {1.0f, 0.0f, -1e-6f}});
  EXPECT_EQ(load_error(dir / "hf.exr").code(), ExitCode::invalid_input);
}

TEST(NormalMapInput, OneChannelImageIsCalledAHeightMap) {
  test::ScratchDir dir;
  save_image(dir / "height.png", Image{2, 2, 1, {0.1f, 0.2f, 0.3f, 0.4f}}, {.png_bits = 8});
  const Error e = load_error(dir / "height.png");
  EXPECT_EQ(e.code(), ExitCode::invalid_input);
  EXPECT_NE(std::string(e.what()).find("height map"), std::string::npos) << e.what();
}

TEST(NormalMapInput, SizeLimitIsEnforcedBeforeDecoding) {
  test::ScratchDir dir;
  Image wide{kMaxNormalMapSide + 1, 1, 3, std::vector<float>(size_t(kMaxNormalMapSide + 1) * 3, 0.5f)};
  save_image(dir / "wide.png", wide, {.png_bits = 8});
  const Error e = load_error(dir / "wide.png");
  EXPECT_EQ(e.code(), ExitCode::invalid_input);
  EXPECT_NE(std::string(e.what()).find("at most 16384"), std::string::npos) << e.what();
  // The limit itself is accepted.
  wide.width = kMaxNormalMapSide;
  wide.pixels.resize(size_t(kMaxNormalMapSide) * 3);
  for (size_t i = 2; i < wide.pixels.size(); i += 3) wide.pixels[i] = 1.0f;
  save_image(dir / "limit.png", wide, {.png_bits = 8});
  EXPECT_EQ(load_normal_map(dir / "limit.png", kStrict).map.width, kMaxNormalMapSide);
}

TEST(NormalMapInput, FileErrorsHaveTheirExitCodes) {
  test::ScratchDir dir;
  EXPECT_EQ(load_error(dir / "absent.png").code(), ExitCode::io_failure);
  std::ofstream(dir / "text.png") << "hello";
  EXPECT_EQ(load_error(dir / "text.png").code(), ExitCode::invalid_input);
}

TEST(NormalMapInput, RecordDescribesTheInput) {
  test::ScratchDir dir;
  save_image(dir / "n.png", Image{3, 2, 4, std::vector<float>(24, 0.75f)}, {.png_bits = 16});
  const LoadedNormalMap m = load_normal_map(dir / "n.png", {YConvention::minus_y, InvalidTexelPolicy::error});
  const InputRecord& r = m.record;
  EXPECT_EQ(r.path, (dir / "n.png").string());
  EXPECT_EQ(r.bytes, std::filesystem::file_size(dir / "n.png"));
  EXPECT_EQ(r.width, 3u);
  EXPECT_EQ(r.height, 2u);
  EXPECT_EQ(r.channels, 4u);
  EXPECT_EQ(r.pixel_format, "uint16");
  EXPECT_EQ(r.convention, "-Y");
  EXPECT_EQ(r.content_hash, file_content_hash(dir / "n.png"));
  const nlohmann::json j = r.to_json();
  for (const char* key : {"path", "content_hash", "bytes", "width", "height", "channels", "pixel_format", "convention",
                          "invalid_policy", "repaired_texels"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["content_hash"], r.content_hash);
}

TEST(NormalMapInput, ContentHashIsXxh3OfTheFileBytes) {
  test::ScratchDir dir;
  std::ofstream(dir / "empty.bin").close();
  // XXH3-64 of no bytes (seed 0) is the published constant 2D06800538D394C2.
  EXPECT_EQ(file_content_hash(dir / "empty.bin"), "xxh3:2d06800538d394c2");
  // Larger than the 1 MiB read buffer; equal content gives equal hashes, one changed byte a different one.
  std::string big(3u << 20, 'a');
  std::ofstream(dir / "a.bin", std::ios::binary) << big;
  std::ofstream(dir / "b.bin", std::ios::binary) << big;
  big[2u << 20] = 'b';
  std::ofstream(dir / "c.bin", std::ios::binary) << big;
  const std::string ha = file_content_hash(dir / "a.bin");
  EXPECT_EQ(ha.size(), 5u + 16u);
  EXPECT_EQ(ha, file_content_hash(dir / "b.bin"));
  EXPECT_NE(ha, file_content_hash(dir / "c.bin"));
  try {
    file_content_hash(dir / "absent.bin");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::io_failure);
  }
}

}  // namespace
}  // namespace mbk
