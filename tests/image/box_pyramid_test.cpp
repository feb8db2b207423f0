// build_coarser_levels / build_box_pyramid against brute force for every channel count (the pyramid is specialised
// for 1 to 4 channels and generic above): every texel of every level is the area-weighted mean of the finest texels
// over its rectangle (formats/mip_levels.h), for odd, thin and one-texel images; the bytes do not depend on the thread
// count; a pixel count that does not match the size is an internal error. Three-channel normal pyramids are also
// checked in normal_pyramid_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "formats/error.h"
#include "formats/mip_levels.h"
#include "libbake/core/hash.h"
#include "libbake/core/parallel.h"
#include "libbake/image/box_pyramid.h"

namespace mbk {
namespace {

Image hashed_image(uint32_t w, uint32_t h, uint32_t channels) {
  Image image{w, h, channels, {}};
  for (uint32_t i = 0; i < w * h * channels; ++i)
    image.pixels.push_back(float(4.0 * unit_from_hash(pcg_hash(i)) - 2.0));
  return image;
}

double overlap(double a, double b, double c, double d) { return std::max(0.0, std::min(b, d) - std::max(a, c)); }

// Channel c's mean over texel (i, j) of a w x h level: every finest texel weighted by its overlap area.
double brute_force_mean(const Image& finest, uint32_t w, uint32_t h, uint32_t i, uint32_t j, uint32_t c) {
  const double tx = double(finest.width) / w, ty = double(finest.height) / h;
  double sum = 0.0, area = 0.0;
  for (uint32_t y = 0; y < finest.height; ++y)
    for (uint32_t x = 0; x < finest.width; ++x) {
      const double a = overlap(i * tx, (i + 1) * tx, x, x + 1.0) * overlap(j * ty, (j + 1) * ty, y, y + 1.0);
      sum += a * finest.at(x, y, c);
      area += a;
    }
  return sum / area;
}

class BoxPyramidShapes : public ::testing::TestWithParam<std::tuple<uint32_t, uint32_t, uint32_t>> {};

TEST_P(BoxPyramidShapes, EachLevelIsTheBruteForceMeanOfCoveredTexels) {
  const auto [w, h, channels] = GetParam();
  const Image finest = hashed_image(w, h, channels);
  const std::vector<Image> pyramid = build_box_pyramid(finest);
  const auto sizes = mip_level_sizes(w, h);
  ASSERT_EQ(pyramid.size(), sizes.size());
  EXPECT_EQ(pyramid[0].pixels, finest.pixels);
  for (size_t k = 1; k < sizes.size(); ++k) {
    const Image& level = pyramid[k];
    ASSERT_EQ(level.width, sizes[k].width);
    ASSERT_EQ(level.height, sizes[k].height);
    ASSERT_EQ(level.channels, channels);
    for (uint32_t j = 0; j < level.height; ++j)
      for (uint32_t i = 0; i < level.width; ++i)
        for (uint32_t c = 0; c < channels; ++c)
          ASSERT_NEAR(level.at(i, j, c), brute_force_mean(finest, level.width, level.height, i, j, c), 4e-7)
              << "level " << k << " texel (" << i << ", " << j << ") channel " << c;
  }
}

TEST_P(BoxPyramidShapes, SameBytesWhateverTheThreadCount) {
  const auto [w, h, channels] = GetParam();
  const Image finest = hashed_image(w, h, channels);
  const int before = thread_count();
  set_thread_count(1);
  const std::vector<Image> one = build_coarser_levels(finest.pixels, w, h, channels);
  set_thread_count(3);
  const std::vector<Image> three = build_coarser_levels(finest.pixels, w, h, channels);
  set_thread_count(before);
  ASSERT_EQ(one.size(), three.size());
  for (size_t k = 0; k < one.size(); ++k) EXPECT_EQ(one[k].pixels, three[k].pixels) << "level " << k + 1;
}

INSTANTIATE_TEST_SUITE_P(ChannelsAndSizes, BoxPyramidShapes,
                         ::testing::Values(std::tuple{13u, 6u, 1u}, std::tuple{13u, 6u, 2u}, std::tuple{7u, 9u, 3u},
                                           std::tuple{13u, 6u, 4u}, std::tuple{5u, 11u, 5u}, std::tuple{1u, 9u, 7u},
                                           std::tuple{32u, 32u, 4u}, std::tuple{64u, 1u, 2u}));

TEST(BoxPyramid, OneTexelHasNoCoarserLevelAndAnEmptyImageNoLevel) {
  const Image one = hashed_image(1, 1, 4);
  EXPECT_TRUE(build_coarser_levels(one.pixels, 1, 1, 4).empty());
  ASSERT_EQ(build_box_pyramid(one).size(), 1u);
  EXPECT_TRUE(build_box_pyramid(Image{}).empty());
  EXPECT_TRUE(build_coarser_levels({}, 0, 5, 3).empty());
}

TEST(BoxPyramid, PixelCountNotMatchingTheSizeIsAnInternalError) {
  const Image image = hashed_image(4, 4, 3);
  EXPECT_THROW(build_coarser_levels(image.pixels, 4, 4, 2), Error);
  EXPECT_THROW(build_coarser_levels(image.pixels, 4, 4, 0), Error);
  EXPECT_THROW(build_coarser_levels(std::span<const float>(image.pixels).first(47), 4, 4, 3), Error);
}

}  // namespace
}  // namespace mbk
