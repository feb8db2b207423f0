// image_io: what save_image stores is what load_image reads back, for each format and bit depth; errors
// carry the documented exit codes.
#include <gtest/gtest.h>

#include <Imath/half.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "formats/error.h"
#include "libbake/image/image_io.h"
#include "tests/image/cli_run.h"

namespace mbk {
namespace {

// A W x H x C image whose values are exact codes of `max_code` (so integer formats store them exactly).
Image coded_image(uint32_t w, uint32_t h, uint32_t c, double max_code) {
  Image im{w, h, c, {}};
  for (uint32_t i = 0; i < w * h * c; ++i)
    im.pixels.push_back(float(double((i * 7919u + 13u) % uint32_t(max_code + 1)) / max_code));
  return im;
}

ExitCode code_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.code();
  }
  return ExitCode::success;
}

TEST(ImageIo, Png8BitStoresCodesExactly) {
  test::ScratchDir dir;
  const Image im = coded_image(7, 5, 3, 255.0);
  save_image(dir / "a.png", im, {.png_bits = 8});
  ImageFileInfo info;
  const Image back = load_image(dir / "a.png", &info);
  EXPECT_EQ(info.pixel_format, "uint8");
  EXPECT_FALSE(info.is_float);
  EXPECT_EQ(info.integer_bits, 8);
  ASSERT_EQ(back.pixels.size(), im.pixels.size());
  for (size_t i = 0; i < im.pixels.size(); ++i) EXPECT_FLOAT_EQ(back.pixels[i], im.pixels[i]) << i;
}

TEST(ImageIo, Png16BitStoresCodesExactly) {
  test::ScratchDir dir;
  const Image im = coded_image(3, 4, 3, 65535.0);
  save_image(dir / "a.png", im, {.png_bits = 16});
  ImageFileInfo info;
  const Image back = load_image(dir / "a.png", &info);
  EXPECT_EQ(info.pixel_format, "uint16");
  EXPECT_EQ(info.integer_bits, 16);
  for (size_t i = 0; i < im.pixels.size(); ++i) EXPECT_FLOAT_EQ(back.pixels[i], im.pixels[i]) << i;
}

TEST(ImageIo, PngRoundsToNearestCodeClampsAndZeroesNaN) {
  test::ScratchDir dir;
  const Image im{5, 1, 1, {0.5f / 255.0f + 1e-4f, 0.5f / 255.0f - 1e-4f, -3.0f, 7.0f, NAN}};
  save_image(dir / "a.png", im, {.png_bits = 8});
  const Image back = load_image(dir / "a.png");
  EXPECT_FLOAT_EQ(back.pixels[0], 1.0f / 255.0f);
  EXPECT_FLOAT_EQ(back.pixels[1], 0.0f);
  EXPECT_FLOAT_EQ(back.pixels[2], 0.0f);
  EXPECT_FLOAT_EQ(back.pixels[3], 1.0f);
  EXPECT_FLOAT_EQ(back.pixels[4], 0.0f);
}

TEST(ImageIo, ExrFloatKeepsValuesBitExact) {
  test::ScratchDir dir;
  const Image im{3, 2, 3, {-1.0f, 0.123456789f, 1e-30f, 3.5f, -0.7071f, 42.0f, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}};
  save_image(dir / "a.exr", im, {.float_bits = 32});
  ImageFileInfo info;
  const Image back = load_image(dir / "a.exr", &info);
  EXPECT_EQ(info.pixel_format, "float");
  EXPECT_TRUE(info.is_float);
  EXPECT_EQ(back.pixels, im.pixels);
}

TEST(ImageIo, ExrHalfRoundsToNearestHalf) {
  test::ScratchDir dir;
  const Image im{2, 2, 3, {-1.0f, 0.1f, 0.3333f, 0.9f, -0.25f, 1e-3f, 0.5f, 0.6f, 0.7f, -0.8f, 0.05f, 0.999f}};
  save_image(dir / "a.exr", im, {.float_bits = 16});
  ImageFileInfo info;
  const Image back = load_image(dir / "a.exr", &info);
  EXPECT_EQ(info.pixel_format, "half");
  for (size_t i = 0; i < im.pixels.size(); ++i) EXPECT_EQ(back.pixels[i], float(Imath::half(im.pixels[i]))) << i;
}

TEST(ImageIo, FormatPathChoosesTheFormat) {
  test::ScratchDir dir;
  // A temporary name whose extension says nothing; the destination's extension picks PNG.
  save_image(dir / "out.partial", coded_image(2, 2, 3, 255.0), {.png_bits = 8}, dir / "final.png");
  const auto bytes = test::file_bytes(dir / "out.partial");
  ASSERT_GE(bytes.size(), 8u);
  EXPECT_EQ(std::string(bytes.begin() + 1, bytes.begin() + 4), "PNG");
  save_image(dir / "out2.png", coded_image(2, 2, 3, 255.0), {}, dir / "final.exr");
  const auto exr = test::file_bytes(dir / "out2.png");
  ASSERT_GE(exr.size(), 4u);
  EXPECT_EQ(exr[0], 0x76);  // OpenEXR magic 76 2f 31 01
  EXPECT_EQ(exr[1], 0x2f);
}

TEST(ImageIo, SameImageGivesByteIdenticalFiles) {
  test::ScratchDir dir;
  const Image im = coded_image(9, 7, 3, 65535.0);
  for (const char* ext : {".png", ".exr", ".tif"}) save_image(dir / (std::string("a") + ext), im);
  // Across a clock-second boundary, so that a time stamp in the file would show.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  for (const char* ext : {".png", ".exr", ".tif"}) {
    save_image(dir / (std::string("b") + ext), im);
    EXPECT_EQ(test::file_bytes(dir / (std::string("a") + ext)), test::file_bytes(dir / (std::string("b") + ext)))
        << ext;
  }
}

TEST(ImageIo, ErrorsCarryTheDocumentedExitCodes) {
  test::ScratchDir dir;
  EXPECT_EQ(code_of([&] { load_image(dir / "absent.png"); }), ExitCode::io_failure);
  EXPECT_EQ(code_of([&] { load_image(dir.path()); }), ExitCode::io_failure);
  std::ofstream(dir / "text.png") << "not an image at all";
  EXPECT_EQ(code_of([&] { load_image(dir / "text.png"); }), ExitCode::invalid_input);
  EXPECT_EQ(code_of([&] { save_image(dir / "a.xyz", coded_image(1, 1, 3, 255.0)); }), ExitCode::bad_command_line);
  EXPECT_EQ(code_of([&] { save_image(dir / "noext", coded_image(1, 1, 3, 255.0)); }), ExitCode::bad_command_line);
  EXPECT_EQ(code_of([&] { save_image(dir / "no" / "such" / "dir.png", coded_image(1, 1, 3, 255.0)); }),
            ExitCode::io_failure);
  EXPECT_EQ(code_of([&] { read_image_header(dir / "absent.exr"); }), ExitCode::io_failure);
}

TEST(ImageIo, HeaderReportsSizeWithoutPixels) {
  test::ScratchDir dir;
  save_image(dir / "a.png", coded_image(13, 6, 4, 255.0), {.png_bits = 8});
  const ImageHeader h = read_image_header(dir / "a.png");
  EXPECT_EQ(h.width, 13u);
  EXPECT_EQ(h.height, 6u);
  EXPECT_EQ(h.info.file_channels, 4u);
  EXPECT_EQ(h.info.pixel_format, "uint8");
}

}  // namespace
}  // namespace mbk
