// Reading colour maps (libbake/colormap/colormap_source.h): integer gradient images are sRGB-decoded to linear,
// float images taken as linear, the middle row of a taller image is used, JSON stops are strict (unknown keys,
// decreasing positions, three stops at one place, colours out of range are errors naming their path).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "formats/error.h"
#include "libbake/colormap/colormap_source.h"
#include "libbake/image/image_io.h"
#include "libbake/image/srgb_transfer.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

// A 5 x 3 gradient whose middle row (1) differs from the others.
Image gradient_image() {
  Image im;
  im.width = 5, im.height = 3, im.channels = 3;
  im.pixels.resize(5 * 3 * 3);
  for (uint32_t row = 0; row < 3; ++row)
    for (uint32_t x = 0; x < 5; ++x)
      for (uint32_t c = 0; c < 3; ++c) im.at(x, row, c) = row == 1 ? float(x * 0.25 * (c + 1) / 3.0) : 1.0f;
  return im;
}

void write_text(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

TEST(ColormapSource, SrgbPngIsDecodedToLinear_MiddleRow) {
  const test::ScratchDir dir;
  const auto path = dir / "gradient.png";
  save_image(path, gradient_image(), {.png_bits = 16});
  const LoadedColormap m = load_colormap_source(path, ColorEncoding::automatic);
  EXPECT_EQ(m.encoding, "srgb");
  ASSERT_EQ(m.curve.knots.size(), 5u);
  for (uint32_t x = 0; x < 5; ++x) {
    EXPECT_DOUBLE_EQ(m.curve.knots[x], (x + 0.5) / 5.0);
    for (uint32_t c = 0; c < 3; ++c) {
      const double code = std::round(x * 0.25 * (c + 1) / 3.0 * 65535.0) / 65535.0;
      EXPECT_NEAR(m.curve.colors[x][c], srgb_to_linear(code), 1e-7);
    }
  }
  EXPECT_EQ(m.domain_min, 0.0);
  EXPECT_EQ(m.domain_max, 1.0);
  EXPECT_EQ(m.record["row"], 1);
  // --encoding linear takes the codes as they are.
  const LoadedColormap raw = load_colormap_source(path, ColorEncoding::linear);
  EXPECT_NEAR(raw.curve.colors[2][2], 0.5, 1e-4);
}

TEST(ColormapSource, FloatExrIsLinear_OneRow) {
  const test::ScratchDir dir;
  Image im = gradient_image();
  im.height = 1;
  im.pixels.assign(im.pixels.begin() + 15, im.pixels.begin() + 30);  // the middle row alone
  im.at(4, 0, 0) = 3.5f;                                             // HDR survives
  const auto path = dir / "gradient.exr";
  save_image(path, im);
  const LoadedColormap m = load_colormap_source(path, ColorEncoding::automatic);
  EXPECT_EQ(m.encoding, "linear");
  EXPECT_EQ(m.curve.colors[4][0], 3.5);
  EXPECT_EQ(m.curve.colors[2][1], float(2 * 0.25 * 2 / 3.0));
}

TEST(ColormapSource, NonFiniteGradientTexelIsAnError_NaN) {
  const test::ScratchDir dir;
  Image im = gradient_image();
  im.at(3, 1, 2) = std::nanf("");
  const auto path = dir / "nan_gradient.exr";
  save_image(path, im);
  try {
    load_colormap_source(path, ColorEncoding::automatic);
    ADD_FAILURE() << "accepted a NaN colour";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(e.message().find("texel (3, 1)"), std::string::npos) << e.message();
  }
}

TEST(ColormapSource, JsonStopsWithAHardEdge) {
  const test::ScratchDir dir;
  const auto path = dir / "stops.json";
  write_text(path, R"({"encoding": "linear", "stops": [{"at": -1, "color": [0, 0, 1]}, {"at": 0.5, "color": 0.25},
                      {"at": 0.5, "color": [1, 0, 0]}, {"at": 2, "color": [4, 4, 4]}]})");
  const LoadedColormap m = load_colormap_source(path, ColorEncoding::automatic);
  EXPECT_EQ(m.curve.knots, (std::vector<double>{-1, 0.5, 0.5, 2}));
  EXPECT_EQ(m.curve.colors[1][2], 0.25);
  EXPECT_EQ(m.domain_min, -1.0);
  EXPECT_EQ(m.domain_max, 2.0);
  EXPECT_EQ(m.record["stops"], 4);
}

TEST(ColormapSource, JsonStopsDefaultToSrgb) {
  const test::ScratchDir dir;
  const auto path = dir / "srgb_stops.json";
  write_text(path, R"({"stops": [{"at": 0, "color": [0.5, 0.5, 0.5]}, {"at": 1, "color": [1, 1, 1]}]})");
  const LoadedColormap m = load_colormap_source(path, ColorEncoding::automatic);
  EXPECT_EQ(m.encoding, "srgb");
  EXPECT_NEAR(m.curve.colors[0][0], 0.21404114, 1e-8);  // sRGB 0.5 is 21.4% linear
}

void expect_invalid(const std::string& json, const std::string& where_part) {
  const test::ScratchDir dir;
  const auto path = dir / "bad.json";
  write_text(path, json);
  try {
    load_colormap_source(path, ColorEncoding::automatic);
    ADD_FAILURE() << "accepted " << json;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input) << e.message();
    EXPECT_NE(e.message().find(where_part), std::string::npos) << e.message();
  }
}

TEST(ColormapSource, JsonErrorsNameTheirPath) {
  expect_invalid(R"({"stops": [{"at": 0, "color": 1}, {"at": 1, "colour": 1}]})", "stops[1]");
  expect_invalid(R"({"stops": [{"at": 0, "color": 1}, {"at": 1, "color": 1}], "gamma": 2})", "gamma");
  expect_invalid(R"({"stops": [{"at": 0.5, "color": 1}, {"at": 0.2, "color": 1}]})", "below knot 0");
  expect_invalid(R"({"stops": [{"at": 0, "color": 1}, {"at": 0, "color": 1}, {"at": 0, "color": 0}]})",
                 "share one position");
  expect_invalid(R"({"stops": [{"at": 0, "color": 1}, {"at": 0, "color": 0}]})", "different positions");
  expect_invalid(R"({"stops": [{"at": 0, "color": 1.5}, {"at": 1, "color": 0}]})", "stops[0].color");
  expect_invalid(R"({"stops": [{"at": 0, "color": 1}]})", "at least two");
  expect_invalid(R"({"stops": [)", "malformed JSON");
  expect_invalid(R"({"stops": [{"at": 0, "color": 1, "at": 0.5}, {"at": 1, "color": 0}]})", "stops[0].at");
}

TEST(ColormapSource, MissingFileIsAnIoFailure) {
  const test::ScratchDir dir;
  try {
    load_colormap_source(dir / "nope.png", ColorEncoding::automatic);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::io_failure);
  }
}

TEST(SrgbTransfer, MatchesTheStandardCurve) {
  EXPECT_EQ(srgb_to_linear(0.0), 0.0);
  EXPECT_NEAR(srgb_to_linear(1.0), 1.0, 1e-15);
  EXPECT_NEAR(srgb_to_linear(0.04045), 0.04045 / 12.92, 1e-12);
  EXPECT_NEAR(srgb_to_linear(std::nextafter(0.04045, 1.0)), 0.04045 / 12.92, 1e-7);  // continuous at the joint
}

}  // namespace
}  // namespace mbk
