// The `sh` asset (libbake/filter/sh_asset.h, formats/kind_sh.cpp): bakes of odd and degenerate sizes in f16
// and f32 pass validate_asset() with no findings; stored levels equal the pyramid (f32 exactly, f16 within
// half an ulp); the window factors are the documented formulas.
#include <gtest/gtest.h>

#include <Imath/half.h>

#include <cmath>
#include <numbers>

#include "formats/asset.h"
#include "formats/validate.h"
#include "libbake/core/parallel.h"
#include "libbake/core/sh_basis.h"
#include "libbake/filter/sh_asset.h"
#include "tests/filter/filter_test_maps.h"

namespace mbk {
namespace {

struct ShAssetCase {
  uint32_t w, h;
  int order;
  ShPrecision precision;
  ShWindow window;
};

class ShAssetCases : public ::testing::TestWithParam<ShAssetCase> {};

TEST_P(ShAssetCases, PassesValidationAndStoresThePyramid) {
  const ShAssetCase c = GetParam();
  const LoadedNormalMap input = test::loaded_map(test::random_normal_map(c.w, c.h, 17));
  const ShPyramid pyramid = build_sh_pyramid(input.map, c.order, Progress::silent());
  const ShBakeOptions options{c.order, c.precision, c.window};
  const std::vector<uint8_t> bytes = bake_sh_asset(input, options, Progress::silent()).serialize();
  const std::vector<Finding> findings = validate_asset(bytes);
  for (const Finding& f : findings) ADD_FAILURE() << f.id << ": " << f.message;
  const Asset a = Asset::parse(bytes, "sh");
  EXPECT_EQ(a.metadata()["parameters"]["order"], c.order);
  EXPECT_EQ(a.metadata()["parameters"]["levels"], pyramid.levels.size() + 1);
  EXPECT_EQ(a.read<float>("normals").size(), size_t(c.w) * c.h * 3);
  for (size_t k = 0; k < pyramid.levels.size(); ++k) {
    const std::vector<float> stored = a.read_as_float("level_" + std::to_string(k + 1));
    const std::vector<float>& exact = pyramid.levels[k].coefficients;
    ASSERT_EQ(stored.size(), exact.size());
    for (size_t i = 0; i < exact.size(); ++i) {
      if (c.precision == ShPrecision::f32) {
        ASSERT_EQ(stored[i], exact[i]);
      } else {  // the f16 nearest the f32 coefficient: within half an ulp of it
        ASSERT_EQ(stored[i], float(Imath::half(exact[i])));
        ASSERT_NEAR(stored[i], exact[i], std::abs(exact[i]) / 2048 + 6e-8);
      }
    }
  }
  const std::vector<float> window = a.read<float>("window");
  const std::vector<double> factors = window_factors(c.window, c.order);
  ASSERT_EQ(window.size(), factors.size());
  for (size_t l = 0; l < window.size(); ++l) EXPECT_EQ(window[l], float(factors[l]));
}

INSTANTIATE_TEST_SUITE_P(SizesPrecisionsWindows, ShAssetCases,
                         ::testing::Values(ShAssetCase{16, 16, 8, ShPrecision::f16, ShWindow::none},
                                           ShAssetCase{7, 5, 3, ShPrecision::f32, ShWindow::hann},
                                           ShAssetCase{1, 1, 2, ShPrecision::f16, ShWindow::lanczos},
                                           ShAssetCase{9, 1, 0, ShPrecision::f32, ShWindow::none},
                                           ShAssetCase{6, 10, 32, ShPrecision::f16, ShWindow::hann},
                                           ShAssetCase{40, 24, 8, ShPrecision::f16, ShWindow::none},
                                           ShAssetCase{26, 12, 4, ShPrecision::f32, ShWindow::none}));

// The bake streams level 1 row by row (and level 2 from pairs of its rows) through parallel loops: the file's
// bytes, statistics included, must not depend on the thread count. Sizes: every level nesting (64 x 32), a
// level from the normals in the middle of the pyramid (26 x 12 -> 13 x 6 -> 6 x 3: 6 x 3 does not nest in
// 13 x 6) and odd sizes.
TEST(ShAsset, BytesIdenticalWhateverTheThreadCount) {
  const int threads = thread_count();
  for (const auto& [w, h] : {std::pair{64u, 32u}, std::pair{26u, 12u}, std::pair{13u, 9u}})
    for (ShPrecision precision : {ShPrecision::f16, ShPrecision::f32}) {
      const LoadedNormalMap input = test::loaded_map(test::random_normal_map(w, h, 23));
      std::vector<std::vector<uint8_t>> files;
      for (int n : {1, 2, 3}) {
        set_thread_count(n);
        files.push_back(bake_sh_asset(input, {6, precision, ShWindow::none}, Progress::silent()).serialize());
      }
      EXPECT_EQ(files[0], files[1]) << w << "x" << h;
      EXPECT_EQ(files[0], files[2]) << w << "x" << h;
    }
  set_thread_count(threads);
}

TEST(ShWindow, FactorsAreTheDocumentedFormulas) {
  const auto none = window_factors(ShWindow::none, 4), hann = window_factors(ShWindow::hann, 4),
             lanczos = window_factors(ShWindow::lanczos, 4);
  for (int l = 0; l <= 4; ++l) {
    const double x = std::numbers::pi * l / 5.0;
    EXPECT_EQ(none[size_t(l)], 1.0);
    EXPECT_NEAR(hann[size_t(l)], 0.5 * (1 + std::cos(x)), 1e-15);
    EXPECT_NEAR(lanczos[size_t(l)], l == 0 ? 1.0 : std::sin(x) / x, 1e-15);
    if (l > 0) {
      EXPECT_LT(hann[size_t(l)], hann[size_t(l) - 1]);
      EXPECT_GT(hann[size_t(l)], 0.0);
      EXPECT_LT(lanczos[size_t(l)], lanczos[size_t(l) - 1]);
    }
  }
  EXPECT_THROW(parse_window("gauss"), Error);
}

}  // namespace
}  // namespace mbk
