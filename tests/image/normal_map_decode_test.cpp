// Decoding normal maps from every file format microbake reads: fixtures with known codes are written by
// the test itself, and the loaded vectors must equal the documented decoding (normal_map.h): unsigned
// codes -> normalize(2v - 1), floats -> normalize(v), -Y flips y, two channels rebuild z.
#include <gtest/gtest.h>

#include <Imath/half.h>
#include <OpenImageIO/imageio.h>

#include <cmath>

#include "formats/error.h"
#include "libbake/image/image_io.h"
#include "libbake/image/normal_map.h"
#include "libbake/image/normal_map_encoding.h"
#include "tests/file_contents.h"
#include "tests/image/cli_run.h"

namespace mbk {
namespace {

// Codes of a 4 x 3 RGB image (8-bit scale): varied tilts, all with z > 0.
const uint8_t kCodes[4 * 3][3] = {{128, 128, 255}, {200, 90, 230},  {30, 220, 180},  {255, 128, 200},
                                  {128, 0, 200},   {60, 60, 240},   {180, 180, 180}, {100, 150, 250},
                                  {10, 128, 160},  {128, 250, 170}, {220, 40, 190},  {140, 120, 129}};

// The codes above as a [0, 1] image; a fourth channel (alpha) is 0.25.
Image code_image(uint32_t channels = 3) {
  Image im{4, 3, channels, {}};
  for (const auto& t : kCodes)
    for (uint32_t c = 0; c < channels; ++c) im.pixels.push_back(c < 3 ? float(t[c] / 255.0) : 0.25f);
  return im;
}

Vec3f expected_from_codes(const uint8_t* t, bool flip_y = false) {
  Vec3 n(2.0 * t[0] / 255.0 - 1.0, 2.0 * t[1] / 255.0 - 1.0, 2.0 * t[2] / 255.0 - 1.0);
  if (flip_y) n.y() = -n.y();
  return n.normalized().cast<float>();
}

void expect_near(const NormalMap& m, const std::function<Vec3f(size_t)>& expected, double tolerance) {
  ASSERT_EQ(m.texels.size(), 12u);
  for (size_t i = 0; i < m.texels.size(); ++i) {
    EXPECT_NEAR((m.texels[i] - expected(i)).norm(), 0.0, tolerance) << "texel " << i << ": " << m.texels[i].transpose();
    EXPECT_NEAR(m.texels[i].norm(), 1.0, 1e-6);
  }
}

LoadedNormalMap load(const std::filesystem::path& p, YConvention c = YConvention::plus_y) {
  return load_normal_map(p, {.convention = c, .invalid = InvalidTexelPolicy::error});
}

TEST(NormalMapDecode, Png8BitMapsCodesTo2vMinus1) {
  test::ScratchDir dir;
  save_image(dir / "n.png", code_image(), {.png_bits = 8});
  const LoadedNormalMap m = load(dir / "n.png");
  EXPECT_EQ(m.record.pixel_format, "uint8");
  expect_near(
      m.map, [](size_t i) { return expected_from_codes(kCodes[i]); }, 1e-6);
}

TEST(NormalMapDecode, Png16BitMapsCodesTo2vMinus1) {
  test::ScratchDir dir;
  // 16-bit codes 257 * c8 plus an offset that only 16 bits can hold.
  Image im{4, 3, 3, {}};
  std::vector<Vec3f> expected;
  for (const auto& t : kCodes) {
    Vec3 n;
    for (int c = 0; c < 3; ++c) {
      const uint32_t code16 = std::min(65535u, t[c] * 257u + 100u);
      im.pixels.push_back(float(code16 / 65535.0));
      n[c] = 2.0 * code16 / 65535.0 - 1.0;
    }
    expected.push_back(n.normalized().cast<float>());
  }
  save_image(dir / "n.png", im, {.png_bits = 16});
  const LoadedNormalMap m = load(dir / "n.png");
  EXPECT_EQ(m.record.pixel_format, "uint16");
  expect_near(
      m.map, [&](size_t i) { return expected[i]; }, 1e-6);
}

TEST(NormalMapDecode, ExrFloatIsTakenAsTheVector) {
  test::ScratchDir dir;
  Image im{4, 3, 3, {}};
  std::vector<Vec3f> expected;
  for (size_t i = 0; i < 12; ++i) {
    const Vec3 v(0.3 * std::sin(double(i)), -0.2 + 0.05 * double(i), 0.5 + 0.1 * double(i));  // not unit length
    for (int c = 0; c < 3; ++c) im.pixels.push_back(float(v[c]));
    expected.push_back(Vec3(im.pixels[3 * i], im.pixels[3 * i + 1], im.pixels[3 * i + 2]).normalized().cast<float>());
  }
  save_image(dir / "n.exr", im, {.float_bits = 32});
  const LoadedNormalMap m = load(dir / "n.exr");
  EXPECT_EQ(m.record.pixel_format, "float");
  expect_near(
      m.map, [&](size_t i) { return expected[i]; }, 1e-6);
}

TEST(NormalMapDecode, ExrHalfIsTakenAsTheVector) {
  test::ScratchDir dir;
  Image im{4, 3, 3, {}};
  std::vector<Vec3f> expected;
  for (size_t i = 0; i < 12; ++i) {
    const Vec3 v(-0.6 + 0.1 * double(i), 0.3 - 0.07 * double(i), 0.9);
    Vec3 h;
    for (int c = 0; c < 3; ++c) im.pixels.push_back(float(v[c])), h[c] = float(Imath::half(float(v[c])));
    expected.push_back(h.normalized().cast<float>());
  }
  save_image(dir / "n.exr", im, {.float_bits = 16});
  const LoadedNormalMap m = load(dir / "n.exr");
  EXPECT_EQ(m.record.pixel_format, "half");
  expect_near(
      m.map, [&](size_t i) { return expected[i]; }, 1e-6);
}

TEST(NormalMapDecode, TgaMapsCodesTo2vMinus1) {
  test::ScratchDir dir;
  save_image(dir / "n.tga", code_image(), {.png_bits = 8});
  const LoadedNormalMap m = load(dir / "n.tga");
  EXPECT_EQ(m.record.pixel_format, "uint8");
  expect_near(
      m.map, [](size_t i) { return expected_from_codes(kCodes[i]); }, 1e-6);
}

TEST(NormalMapDecode, Tiff8And16BitMapCodesTo2vMinus1) {
  test::ScratchDir dir;
  save_image(dir / "n8.tif", code_image(), {.png_bits = 8});
  save_image(dir / "n16.tif", code_image(), {.png_bits = 16});  // 8-bit codes are exact 16-bit codes (x 257)
  const LoadedNormalMap m8 = load(dir / "n8.tif"), m16 = load(dir / "n16.tif");
  EXPECT_EQ(m8.record.pixel_format, "uint8");
  EXPECT_EQ(m16.record.pixel_format, "uint16");
  expect_near(
      m8.map, [](size_t i) { return expected_from_codes(kCodes[i]); }, 1e-6);
  expect_near(
      m16.map, [](size_t i) { return expected_from_codes(kCodes[i]); }, 1e-6);
}

// save_image writes integer TIFFs only; float and signed-integer TIFFs are written with OpenImageIO here.
void write_tiff(const std::filesystem::path& p, OIIO::TypeDesc type, const std::vector<float>& rgb) {
  auto out = OIIO::ImageOutput::create(p.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(p.string(), OIIO::ImageSpec(int(rgb.size() / 3), 1, 3, type)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()));
  ASSERT_TRUE(out->close());
}

TEST(NormalMapDecode, FloatTiffIsTakenAsTheVector) {
  test::ScratchDir dir;
  write_tiff(dir / "n.tif", OIIO::TypeDesc::FLOAT, {-0.5f, 0.25f, 1.0f, 0.1f, 0.2f, 0.3f});
  const LoadedNormalMap m = load(dir / "n.tif");
  EXPECT_EQ(m.record.pixel_format, "float");
  EXPECT_NEAR((m.map.texels[0].cast<double>() - Vec3(-0.5, 0.25, 1.0).normalized()).norm(), 0.0, 1e-6);
  EXPECT_NEAR((m.map.texels[1].cast<double>() - Vec3(0.1, 0.2, 0.3).normalized()).norm(), 0.0, 1e-6);
}

TEST(NormalMapDecode, SignedIntegerTiffIsTakenAsTheVector) {
  test::ScratchDir dir;
  write_tiff(dir / "n.tif", OIIO::TypeDesc::INT16, {-0.5f, 0.25f, 1.0f});
  const LoadedNormalMap m = load(dir / "n.tif");
  EXPECT_EQ(m.record.pixel_format, "int16");
  EXPECT_NEAR((m.map.texels[0].cast<double>() - Vec3(-0.5, 0.25, 1.0).normalized()).norm(), 0.0, 1e-4);
}

TEST(NormalMapDecode, JpegDecodesWithinCompressionError) {
  test::ScratchDir dir;
  // Flat 8 x 8 blocks of one colour survive JPEG's DCT almost exactly; chroma subsampling of a
  // uniform block changes nothing. Allow 2 codes of error per channel.
  Image im{16, 8, 3, {}};
  for (uint32_t r = 0; r < 8; ++r)
    for (uint32_t x = 0; x < 16; ++x) {
      const auto& t = x < 8 ? kCodes[1] : kCodes[2];
      for (int c = 0; c < 3; ++c) im.pixels.push_back(float(t[c] / 255.0));
    }
  save_image(dir / "n.jpg", im, {.png_bits = 8});
  const LoadedNormalMap m = load(dir / "n.jpg");
  EXPECT_EQ(m.record.pixel_format, "uint8");
  const double tol = 2.0 * 2.0 / 255.0 * std::sqrt(3.0);
  EXPECT_NEAR((m.map.at(3, 4) - expected_from_codes(kCodes[1])).norm(), 0.0, tol);
  EXPECT_NEAR((m.map.at(12, 4) - expected_from_codes(kCodes[2])).norm(), 0.0, tol);
}

TEST(NormalMapDecode, MinusYFlipsGreenOnly) {
  test::ScratchDir dir;
  save_image(dir / "n.png", code_image(), {.png_bits = 8});
  const LoadedNormalMap plus = load(dir / "n.png", YConvention::plus_y),
                        minus = load(dir / "n.png", YConvention::minus_y);
  expect_near(
      minus.map, [](size_t i) { return expected_from_codes(kCodes[i], true); }, 1e-6);
  for (size_t i = 0; i < 12; ++i) {
    EXPECT_EQ(minus.map.texels[i].x(), plus.map.texels[i].x());
    EXPECT_EQ(minus.map.texels[i].y(), -plus.map.texels[i].y());
    EXPECT_EQ(minus.map.texels[i].z(), plus.map.texels[i].z());
  }
  EXPECT_EQ(minus.record.convention, "-Y");
  EXPECT_EQ(plus.record.convention, "+Y");
}

TEST(NormalMapDecode, SavedMapsLoadBackInTheirConvention) {
  test::ScratchDir dir;
  save_image(dir / "n.png", code_image(), {.png_bits = 8});
  const NormalMap original = load(dir / "n.png").map;
  for (YConvention c : {YConvention::plus_y, YConvention::minus_y})
    for (const char* name : {"a.png", "a.exr", "a.tif"}) {
      save_normal_map(dir / name, original, c);
      const NormalMap back = load(dir / name, c).map;
      for (size_t i = 0; i < 12; ++i)
        EXPECT_NEAR((back.texels[i] - original.texels[i]).norm(), 0.0, 4.0 / 65535.0)
            << name << " " << convention_name(c);
    }
}

// save_normal_image (the normals as a 3-channel image, written without a copy for +Y EXR) writes the very file that
// save_normal_map writes for the same vectors, in every encoding and convention.
TEST(NormalMapDecode, NormalImagesSaveAsTheSameFileAsTheirMap) {
  test::ScratchDir dir;
  save_image(dir / "n.png", code_image(), {.png_bits = 8});
  const NormalMap map = load(dir / "n.png").map;
  Image image{map.width, map.height, 3, {}};
  for (const Vec3f& n : map.texels) image.pixels.insert(image.pixels.end(), {n.x(), n.y(), n.z()});
  for (YConvention c : {YConvention::plus_y, YConvention::minus_y})
    for (const char* ext : {".png", ".exr", ".tif"}) {
      save_normal_map(dir / (std::string("map") + ext), map, c);
      save_normal_image(dir / (std::string("image") + ext), image, c);
      EXPECT_EQ(test::file_bytes(dir / (std::string("map") + ext)),
                test::file_bytes(dir / (std::string("image") + ext)))
          << ext << " " << convention_name(c);
    }
}

// Float normal maps are written uncompressed (zip gains ~4% on unit normals' mantissas at ~25 MB/s per core), other
// EXR images zip-compressed: a flat map, which zip would shrink to almost nothing, keeps its 12 bytes per texel.
TEST(NormalMapDecode, FloatNormalMapsAreStoredUncompressedOtherImagesZipped) {
  test::ScratchDir dir;
  NormalMap flat;
  flat.width = flat.height = 128;
  flat.texels.assign(128 * 128, Vec3f(0, 0, 1));
  save_normal_map(dir / "flat.exr", flat);
  EXPECT_GE(std::filesystem::file_size(dir / "flat.exr"), 128u * 128u * 12u);
  save_image(dir / "flat_image.exr", encode_normal_map(flat, NormalEncoding::float_vector));
  EXPECT_LT(std::filesystem::file_size(dir / "flat_image.exr"), 128u * 128u * 12u / 10u);
  EXPECT_EQ(load(dir / "flat.exr").map.texels, flat.texels);
}

TEST(NormalMapDecode, TwoChannelFloatRebuildsZ) {
  test::ScratchDir dir;
  const Image im{3, 1, 2, {0.6f, 0.0f, -0.3f, 0.4f, 0.8f, 0.8f}};  // last one lies outside the unit disk
  save_image(dir / "xy.exr", im, {.float_bits = 32});
  const LoadedNormalMap m = load(dir / "xy.exr");
  EXPECT_EQ(m.record.channels, 2u);
  EXPECT_NEAR((m.map.texels[0] - Vec3f(0.6f, 0.0f, 0.8f)).norm(), 0.0, 1e-6);
  const double z1 = std::sqrt(1.0 - 0.09 - 0.16);
  EXPECT_NEAR((m.map.texels[1].cast<double>() - Vec3(-0.3, 0.4, z1)).norm(), 0.0, 1e-6);
  // Outside the disk: z = 0, then renormalised onto the horizon.
  EXPECT_NEAR((m.map.texels[2].cast<double>() - Vec3(std::sqrt(0.5), std::sqrt(0.5), 0.0)).norm(), 0.0, 1e-6);
}

TEST(NormalMapDecode, TwoChannelPngRebuildsZFromUnsignedCodes) {
  test::ScratchDir dir;
  // A two-channel PNG is stored as grey + alpha: the second channel must not be treated as coverage.
  const Image im{2, 1, 2, {float(200 / 255.0), float(90 / 255.0), 0.5f, 0.5f}};
  save_image(dir / "xy.png", im, {.png_bits = 8});
  const LoadedNormalMap m = load(dir / "xy.png");
  const double x = 2.0 * 200 / 255.0 - 1.0, y = 2.0 * 90 / 255.0 - 1.0;
  EXPECT_NEAR((m.map.texels[0].cast<double>() - Vec3(x, y, std::sqrt(1 - x * x - y * y))).norm(), 0.0, 1e-6);
  const double h = 2.0 * 128 / 255.0 - 1.0;  // 0.5 rounds to code 128
  EXPECT_NEAR((m.map.texels[1].cast<double>() - Vec3(h, h, std::sqrt(1 - 2 * h * h))).norm(), 0.0, 1e-6);
}

TEST(NormalMapDecode, AlphaDoesNotScaleNormals) {
  test::ScratchDir dir;
  Image im = code_image(4);  // alpha 0.25 everywhere
  im.pixels[3] = 0.0f;       // and one fully transparent texel
  save_image(dir / "rgba.png", im, {.png_bits = 8});
  save_image(dir / "rgba.tga", im, {.png_bits = 8});
  save_image(dir / "rgba.tif", im, {.png_bits = 8});
  for (const char* name : {"rgba.png", "rgba.tga", "rgba.tif"}) {
    const LoadedNormalMap m = load(dir / name);
    EXPECT_EQ(m.record.channels, 4u) << name;
    expect_near(
        m.map, [](size_t i) { return expected_from_codes(kCodes[i]); }, 1e-6);
  }
}

TEST(NormalMapDecode, RowZeroIsTheTopRowAndNonSquareSizesWork) {
  test::ScratchDir dir;
  Image im{7, 3, 3, std::vector<float>(63, 0.5f)};
  for (size_t i = 2; i < 63; i += 3) im.pixels[i] = 1.0f;
  im.at(6, 0, 0) = 1.0f;  // top-right texel tilts to +x
  im.at(0, 2, 1) = 1.0f;  // bottom-left texel tilts to +y
  save_image(dir / "n.png", im, {.png_bits = 16});
  const LoadedNormalMap m = load(dir / "n.png");
  ASSERT_EQ(m.map.width, 7u);
  ASSERT_EQ(m.map.height, 3u);
  EXPECT_GT(m.map.at(6, 0).x(), 0.5f);
  EXPECT_GT(m.map.at(0, 2).y(), 0.5f);
  EXPECT_NEAR(m.map.at(3, 1).z(), 1.0f, 1e-4f);
}

TEST(NormalMapDecode, OneByOneMapLoads) {
  test::ScratchDir dir;
  save_image(dir / "n.png", Image{1, 1, 3, {0.75f, 0.5f, 0.9f}}, {.png_bits = 16});
  const LoadedNormalMap m = load(dir / "n.png");
  ASSERT_EQ(m.map.texels.size(), 1u);
  EXPECT_NEAR(m.map.texels[0].norm(), 1.0f, 1e-6f);
  EXPECT_GT(m.map.texels[0].x(), 0.4f);
}

// decode_normal_map is what load_normal_map runs after the image library (and what tests/fuzz/fuzz_normal_map.cpp
// fuzzes): the same buffer and stored type must give the same texels and record as the file.
TEST(NormalMapDecode, DecodingABufferEqualsLoadingTheFile) {
  test::ScratchDir dir;
  save_image(dir / "n.png", code_image(), {.png_bits = 8});
  const LoadedNormalMap file = load(dir / "n.png");
  // The buffer as the image library hands it over (its uint8 -> float conversion, not code / 255.0 in double).
  ImageFileInfo info;
  const Image decoded = load_image(dir / "n.png", &info);
  EXPECT_EQ(info.pixel_format, "uint8");
  const LoadedNormalMap buffer =
      decode_normal_map(decoded, info, {.convention = YConvention::plus_y}, (dir / "n.png").string());
  ASSERT_EQ(buffer.map.texels.size(), file.map.texels.size());
  for (size_t i = 0; i < file.map.texels.size(); ++i) EXPECT_EQ(buffer.map.texels[i], file.map.texels[i]) << i;
  EXPECT_EQ(buffer.record.convention, file.record.convention);
  EXPECT_EQ(buffer.record.convention_evidence, file.record.convention_evidence);
  EXPECT_EQ(buffer.record.pixel_format, "uint8");
}

TEST(NormalMapDecode, BuffersThatNoFileGivesAreHandled) {
  const ImageFileInfo floats{
      .pixel_format = "float", .is_float = true, .is_signed = false, .integer_bits = 0, .file_channels = 3};
  const LoadedNormalMap empty = decode_normal_map(Image{0, 0, 3, {}}, floats, {}, "empty");
  EXPECT_TRUE(empty.map.texels.empty());
  EXPECT_EQ(empty.record.convention, "+Y");  // undecidable: read as +Y
  try {
    decode_normal_map(Image{2, 1, 1, {0.5f, 0.5f}}, floats, {}, "grey");
    FAIL() << "accepted one channel";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
  }
  try {
    decode_normal_map(Image{2, 2, 3, {0, 0, 1}}, floats, {}, "short");
    FAIL() << "accepted a buffer shorter than its size";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::runtime_failure);
  }
  const Image inf{1, 1, 3, {INFINITY, 0, 1}};
  EXPECT_THROW(decode_normal_map(inf, floats, {}, "inf"), Error);
  const LoadedNormalMap repaired =
      decode_normal_map(inf, floats, {.convention = std::nullopt, .invalid = InvalidTexelPolicy::repair}, "inf");
  EXPECT_EQ(repaired.map.texels[0], Vec3f(0, 0, 1));
  EXPECT_EQ(repaired.record.repaired_texels, 1u);
}

TEST(NormalMapDecode, ParseConventionAcceptsDocumentedNames) {
  EXPECT_EQ(parse_convention("+Y"), YConvention::plus_y);
  EXPECT_EQ(parse_convention("opengl"), YConvention::plus_y);
  EXPECT_EQ(parse_convention("OpenGL"), YConvention::plus_y);
  EXPECT_EQ(parse_convention("-y"), YConvention::minus_y);
  EXPECT_EQ(parse_convention("DirectX"), YConvention::minus_y);
  EXPECT_EQ(convention_name(YConvention::plus_y), "+Y");
  EXPECT_EQ(convention_name(YConvention::minus_y), "-Y");
  try {
    parse_convention("up");
    FAIL() << "accepted 'up'";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_command_line);
  }
}

}  // namespace
}  // namespace mbk
