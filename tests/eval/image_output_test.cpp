// compare's metrics against their definitions, and the PNG tone curve (clamp + sRGB OETF).
#include <gtest/gtest.h>

#include <cmath>

#include "formats/error.h"
#include "libbake/eval/image_difference.h"
#include "libbake/eval/render_output.h"

namespace mbk {
namespace {

Image constant_image(uint32_t w, uint32_t h, uint32_t c, float v) {
  Image i;
  i.width = w;
  i.height = h;
  i.channels = c;
  i.pixels.assign(size_t(w) * h * c, v);
  return i;
}

TEST(ImageDifference, MetricsMatchTheirDefinitions) {
  const Image reference = constant_image(4, 3, 3, 0.5f);
  Image a = reference;
  for (size_t i = 0; i < a.pixels.size(); i += 2) a.pixels[i] += 0.25f;  // half the values off by 0.25
  const ImageDifference d = compare_images(a, reference);
  EXPECT_EQ(d.values, 36u);
  EXPECT_DOUBLE_EQ(d.mse, 0.25 * 0.25 / 2);
  EXPECT_DOUBLE_EQ(d.rmse, std::sqrt(0.25 * 0.25 / 2));
  EXPECT_DOUBLE_EQ(d.relative_mse, (0.25 * 0.25 / (0.25 + 0.01)) / 2);
  EXPECT_DOUBLE_EQ(d.psnr_db, 10 * std::log10(1 / d.mse));
  EXPECT_DOUBLE_EQ(d.max_abs, 0.25);
  const ImageDifference same = compare_images(reference, reference);
  EXPECT_EQ(same.rmse, 0.0);
  EXPECT_TRUE(std::isinf(same.psnr_db));
}

TEST(ImageDifference, BlockL1IsTheRelativeL1OfBlockMeans) {
  // 5 x 3 pixels, one channel, 2 x 2 blocks: blocks of 4, 4, 2 (top) and 2, 2, 1 (bottom) pixels.
  const Image reference = constant_image(5, 3, 1, 1.0f);
  Image a = reference;
  a.pixels[0] = 3.0f;   // +2 in block (0, 0) ...
  a.pixels[1] = -1.0f;  // ... and -2: its mean is 1 again
  a.pixels[14] = 2.0f;  // block (2, 1), one pixel: off by 1 (of 6 block means of 1)
  EXPECT_DOUBLE_EQ(compare_images(a, reference, 2).block_relative_l1, 1.0 / 6.0);
  a.pixels[1] = 1.0f;  // now block (0, 0) is off by 2 / 4
  EXPECT_DOUBLE_EQ(compare_images(a, reference, 2).block_relative_l1, 1.5 / 6.0);
  EXPECT_DOUBLE_EQ(compare_images(a, reference, 1).block_relative_l1, 3.0 / 15.0);  // plain relative L1
  const Image black = constant_image(5, 3, 1, 0.0f);
  EXPECT_EQ(compare_images(black, black).block_relative_l1, 0.0);
  EXPECT_TRUE(std::isinf(compare_images(reference, black).block_relative_l1));
}

TEST(ImageDifference, SizeOrChannelMismatchAndNonFiniteValuesAreInvalidInput) {
  const Image a = constant_image(4, 3, 3, 0.5f);
  for (const Image& b : {constant_image(3, 4, 3, 0.5f), constant_image(4, 3, 4, 0.5f)}) {
    try {
      compare_images(a, b);
      ADD_FAILURE();
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::invalid_input);
      EXPECT_NE(std::string(e.what()).find("differ in size"), std::string::npos);
    }
  }
  Image nan = a;
  nan.at(2, 1, 0) = NAN;
  try {
    compare_images(a, nan);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_EQ(e.where(), "pixel (2, 1)");
  }
}

TEST(RenderOutput, ToneCurveIsClampedSrgb) {
  EXPECT_EQ(srgb_oetf(0.0), 0.0);
  EXPECT_NEAR(srgb_oetf(1.0), 1.0, 1e-15);
  EXPECT_NEAR(srgb_oetf(0.18), 0.4613561295, 1e-9);  // middle grey
  // The two pieces meet at the threshold (continuity to 1e-7, as the standard's constants are rounded).
  EXPECT_NEAR(srgb_oetf(0.0031308), 12.92 * 0.0031308, 1e-7);
  EXPECT_NEAR(srgb_oetf(std::nextafter(0.0031308, 1.0)), 12.92 * 0.0031308, 1e-7);
  Image hdr = constant_image(1, 1, 3, 0.0f);
  hdr.pixels = {-1.0f, 0.5f, 7.0f};
  const Image ldr = tone_map_for_display(hdr);
  EXPECT_EQ(ldr.pixels[0], 0.0f);
  EXPECT_FLOAT_EQ(ldr.pixels[1], float(srgb_oetf(0.5)));
  EXPECT_FLOAT_EQ(ldr.pixels[2], 1.0f);
  EXPECT_TRUE(is_render_extension("a.EXR"));
  EXPECT_TRUE(is_render_extension("dir/a.png"));
  EXPECT_FALSE(is_render_extension("a.jpg"));
}

}  // namespace
}  // namespace mbk
