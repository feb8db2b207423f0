// Test fixtures for the `colormap` kind: a small valid asset built by hand from formats/SPEC.md "Kind 7: colormap"
// (independently of the bake: the table by numerical quadrature, tests/colormap/colormap_quadrature.h), a
// 4-knot map with a hard edge tabulated at 5 means x 4 sigmas; and readable corruptions of it, one per colormap
// finding (tests/formats/corrupt_fixtures_test.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/asset_writer.h"
#include "formats/byte_io.h"
#include "tests/colormap/colormap_quadrature.h"
#include "tests/formats/asset_fixtures.h"

namespace mbk::test {

inline constexpr uint32_t kColormapFixtureWidth = 5, kColormapFixtureHeight = 4;

// Sections in writing order: knots (0), colors (1), table (2). Colours are float-exact, so the quadrature of the
// stored map is the table's definition.
inline std::vector<uint8_t> colormap_bytes(const nlohmann::json& parameters) {
  const PiecewiseLinearMap map{{0.0, 0.25, 0.25, 1.0},
                               {{0, 0, 0}, {0.5, 0.25, 0.125}, {0.875, 0.875, 0.125}, {1, 1, 1}}};
  const uint32_t W = kColormapFixtureWidth, H = kColormapFixtureHeight;
  std::vector<float> knots, colors, table;
  for (size_t k = 0; k < map.x.size(); ++k) {
    knots.push_back(float(map.x[k]));
    for (double c : map.c[k]) colors.push_back(float(c));
  }
  for (uint32_t j = 0; j < H; ++j)
    for (uint32_t i = 0; i < W; ++i)
      for (double v : gaussian_average_by_quadrature(map, i / double(W - 1), 0.5 * j / double(H - 1)))
        table.push_back(float(v));
  nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                         {"parameters", parameters},
                         {"conventions", {{"color_space", "linear RGB"}}},
                         {"statistics", nlohmann::json::object()}};
  AssetWriter w("colormap", meta);
  w.add<float>("knots", {4}, knots);
  w.add<float>("colors", {4, 3}, colors);
  w.add<float>("table", {H, W, 3}, table);
  return w.serialize();
}

inline nlohmann::json colormap_fixture_parameters() {
  return {{"width", kColormapFixtureWidth},
          {"height", kColormapFixtureHeight},
          {"mean_min", 0.0},
          {"mean_max", 1.0},
          {"sigma_max", 0.5}};
}

inline std::vector<uint8_t> valid_colormap_bytes() { return colormap_bytes(colormap_fixture_parameters()); }

// The valid fixture with element `index` of section `section` (0..2, order above) set to `value`, resealed.
inline std::vector<uint8_t> colormap_with_value(size_t section, size_t index, float value) {
  std::vector<uint8_t> f = valid_colormap_bytes();
  store_le<float>(&f[section_data_offset(f, section) + 4 * index], value);
  reseal_section(f, section);
  return f;
}

// The valid fixture's table element (row j, column i, channel c) moved by `delta`, resealed.
inline std::vector<uint8_t> colormap_with_table_delta(uint32_t j, uint32_t i, uint32_t c, float delta) {
  std::vector<uint8_t> f = valid_colormap_bytes();
  const size_t at = section_data_offset(f, 2) + 4 * ((size_t(j) * kColormapFixtureWidth + i) * 3 + c);
  store_le<float>(&f[at], load_le<float>(&f[at]) + delta);
  reseal_section(f, 2);
  return f;
}

// The valid fixture with one parameter replaced (the table keeps its 4 x 5 shape).
inline std::vector<uint8_t> colormap_with_parameter(const std::string& key, const nlohmann::json& value) {
  nlohmann::json p = colormap_fixture_parameters();
  p[key] = value;
  return colormap_bytes(p);
}

}  // namespace mbk::test
