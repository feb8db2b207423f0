// The moment pyramid (libbake/colormap/moment_pyramid.h): every texel of every level gives the exact mean and
// variance of the driver over its box footprint (brute force over the finest texels with fractional coverage),
// for non-power-of-two, power-of-two, 1 x 1, constant and far-from-zero drivers; trilinear lookups at texel
// centres return those moments; the asset passes validate, reads back, and is the same whatever the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "formats/asset.h"
#include "formats/error.h"
#include "formats/mip_levels.h"
#include "formats/validate.h"
#include "libbake/colormap/moment_pyramid.h"
#include "libbake/core/parallel.h"
#include "libbake/image/image_io.h"
#include "tests/formats/asset_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

Driver make_driver(uint32_t w, uint32_t h, double offset, double amplitude) {
  Driver d;
  d.width = w, d.height = h;
  for (uint32_t row = 0; row < h; ++row)
    for (uint32_t x = 0; x < w; ++x)
      d.values.push_back(
          float(offset + amplitude * (0.5 * std::sin(0.7 * x + 1.9 * row) + 0.3 * std::cos(2.3 * x * row))));
  d.record = {{"path", "in-memory"}};
  return d;
}

// Mean and variance of the driver over level k texel (i, j)'s rectangle, in double, weighting each finest texel by
// the area of its overlap (test::overlap_length).
std::pair<double, double> brute_force_moments(const Driver& d, uint32_t lw, uint32_t lh, uint32_t i, uint32_t j) {
  const double tx = double(d.width) / lw, ty = double(d.height) / lh;
  double area = 0, sum = 0;
  std::vector<std::pair<double, double>> weighted;
  for (uint32_t y = 0; y < d.height; ++y)
    for (uint32_t x = 0; x < d.width; ++x) {
      const double a = test::overlap_length(i * tx, (i + 1) * tx, x, x + 1.0) *
                       test::overlap_length(j * ty, (j + 1) * ty, y, y + 1.0);
      if (a == 0) continue;
      const double f = d.values[size_t(y) * d.width + x];
      weighted.push_back({a, f});
      area += a, sum += a * f;
    }
  const double mean = sum / area;
  double var = 0;
  for (const auto& [a, f] : weighted) var += a * (f - mean) * (f - mean);
  return {mean, var / area};
}

void expect_exact_box_moments(const Driver& d, double tolerance) {
  const MomentPyramid p = build_moment_pyramid(d);
  const auto sizes = mip_level_sizes(d.width, d.height);
  ASSERT_EQ(p.levels.size(), sizes.size());
  for (size_t k = 0; k < sizes.size(); ++k)
    for (uint32_t j = 0; j < sizes[k].height; ++j)
      for (uint32_t i = 0; i < sizes[k].width; ++i) {
        const auto [mean, var] = brute_force_moments(d, sizes[k].width, sizes[k].height, i, j);
        // The texel centre at integer lod k reads exactly this texel.
        const Vec2 uv((i + 0.5) / sizes[k].width, 1.0 - (j + 0.5) / sizes[k].height);
        const FootprintMoments m = sample_moments(p, uv, double(k));
        ASSERT_NEAR(m.mean, mean, tolerance) << "level " << k << " texel " << i << ", " << j;
        ASSERT_NEAR(m.variance, var, tolerance) << "level " << k << " texel " << i << ", " << j;
      }
}

TEST(MomentPyramid, ExactBoxMeansAndVariances_NonPowerOfTwo) {
  expect_exact_box_moments(make_driver(37, 23, 0.5, 0.8), 2e-7);
}

TEST(MomentPyramid, ExactBoxMeansAndVariances_PowerOfTwo) {
  expect_exact_box_moments(make_driver(64, 32, 0.5, 0.8), 2e-7);
}

TEST(MomentPyramid, ExactBoxMeansAndVariances_OneRow) { expect_exact_box_moments(make_driver(129, 1, 0.5, 0.8), 2e-7); }

TEST(MomentPyramid, OneByOneHasZeroVariance) {
  const MomentPyramid p = build_moment_pyramid(make_driver(1, 1, 0.3, 1.0));
  ASSERT_EQ(p.levels.size(), 1u);
  const FootprintMoments m = sample_moments(p, {0.7, 0.2}, 3.0);
  EXPECT_EQ(m.variance, 0.0);
  EXPECT_NEAR(m.mean, make_driver(1, 1, 0.3, 1.0).values[0], 1e-7);
}

TEST(MomentPyramid, ConstantDriverHasZeroVarianceEverywhere) {
  Driver d = make_driver(13, 7, 0.0, 0.0);
  for (double& v : d.values) v = double(0.3f);  // drivers are float images
  const MomentPyramid p = build_moment_pyramid(d);
  for (double lod : {0.0, 0.5, 1.7, 3.0})
    for (double u : {0.0, 0.31, 0.99}) {
      const FootprintMoments m = sample_moments(p, {u, 0.4}, lod);
      EXPECT_EQ(m.variance, 0.0);
      EXPECT_NEAR(m.mean, 0.3, 1e-7);
    }
}

TEST(MomentPyramid, FarFromZeroDriverKeepsItsVariance_Shift) {
  // Heights around 1e4 with variance ~1e-2: unshifted float moments would lose the variance entirely
  // (E[f^2] ~ 1e8 has an ulp of 8); the shift keeps it to float precision of the deviations.
  expect_exact_box_moments(make_driver(21, 19, 1.0e4, 0.2), 2e-6);
}

TEST(MomentPyramid, TrilinearLookupBlendsMomentsNotVariances) {
  const MomentPyramid p = build_moment_pyramid(make_driver(16, 16, 0.5, 0.8));
  const Vec2 uv(0.3, 0.6);
  const FootprintMoments a = sample_moments(p, uv, 1.0), b = sample_moments(p, uv, 2.0), m = sample_moments(p, uv, 1.5);
  const double m2 = 0.5 * (a.variance + a.mean * a.mean) + 0.5 * (b.variance + b.mean * b.mean);
  EXPECT_NEAR(m.mean, 0.5 * (a.mean + b.mean), 1e-12);
  EXPECT_NEAR(m.variance, m2 - m.mean * m.mean, 1e-9);
  EXPECT_GE(m.variance, 0.5 * (a.variance + b.variance) - 1e-12);  // the spread of the means adds variance
  EXPECT_TRUE(std::isnan(sample_moments(p, uv, std::nan("")).mean));
}

TEST(MomentPyramid, DriverImageWithNaNIsAnError_NaN) {
  Image im;
  im.width = 4, im.height = 3, im.channels = 1;
  im.pixels.assign(12, 0.25f);
  im.pixels[6] = std::nanf("");
  const test::ScratchDir dir;
  const auto path = dir / "nan.exr";
  save_image(path, im);
  try {
    load_driver(path, 0);
    ADD_FAILURE() << "accepted a NaN driver";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(e.message().find("texel (2, 1)"), std::string::npos) << e.message();
  }
  // A single-channel float image loads as is.
  im.pixels[6] = 7.5f;
  save_image(path, im);
  const Driver d = load_driver(path, 0);
  EXPECT_EQ(d.values[6], 7.5);
  EXPECT_EQ(d.record["channel"], 0);
}

TEST(MomentPyramid, ExactBoxMomentsOnARealHeightMap) {
  const std::filesystem::path path = std::filesystem::path(MICROBAKE_REAL_DATA_DIR) / "brick_floor_height.png";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no real data at " << path;
  const Driver d = load_driver(path, 0);
  const MomentPyramid p = build_moment_pyramid(d);
  const auto sizes = mip_level_sizes(d.width, d.height);
  // Every texel of levels 6 and up (16 x 16 texels and coarser, footprints of 64^2 finest texels and more).
  for (size_t k = 6; k < sizes.size(); ++k)
    for (uint32_t j = 0; j < sizes[k].height; ++j)
      for (uint32_t i = 0; i < sizes[k].width; ++i) {
        const auto [mean, var] = brute_force_moments(d, sizes[k].width, sizes[k].height, i, j);
        const Vec2 uv((i + 0.5) / sizes[k].width, 1.0 - (j + 0.5) / sizes[k].height);
        const FootprintMoments m = sample_moments(p, uv, double(k));
        ASSERT_NEAR(m.mean, mean, 1e-6) << "level " << k;
        ASSERT_NEAR(m.variance, var, 1e-6) << "level " << k;
      }
}

std::vector<uint8_t> moments_bytes(const Driver& d) {
  return moments_asset_writer(build_moment_pyramid(d), d).serialize();
}

TEST(MomentsAsset, PassesValidationAndReadsBack) {
  for (const Driver& d :
       {make_driver(37, 23, 0.5, 0.8), make_driver(1, 1, 0.5, 0.8), make_driver(256, 200, 1e3, 5.0)}) {
    const auto bytes = moments_bytes(d);
    for (const Finding& f : validate_asset(bytes)) ADD_FAILURE() << f.id << " " << f.message;
    const MomentPyramid back = read_moment_pyramid(Asset::parse(bytes, "test"));
    const MomentPyramid p = build_moment_pyramid(d);
    EXPECT_EQ(back.shift, p.shift);
    ASSERT_EQ(back.levels.size(), p.levels.size());
    for (size_t k = 0; k < p.levels.size(); ++k) EXPECT_EQ(back.levels[k].pixels, p.levels[k].pixels);
  }
}

TEST(MomentsAsset, SameBytesWhateverTheThreadCount) {
  const int before = thread_count();
  set_thread_count(1);
  const auto one = moments_bytes(make_driver(67, 45, 0.5, 0.8));
  set_thread_count(3);
  const auto three = moments_bytes(make_driver(67, 45, 0.5, 0.8));
  set_thread_count(before);
  EXPECT_EQ(one, three);
}

}  // namespace
}  // namespace mbk
