// Test fixtures for the `lut` kind: a small valid asset built by hand from formats/SPEC.md "Kind 10: lut"
// (independently of the bake): channel n_x five knots of a non-linear monotone map, channel n_y a one-knot
// (constant) channel; and readable corruptions of it, one per lut finding (tests/formats/corrupt_fixtures_test.cpp).
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "formats/asset_writer.h"
#include "formats/byte_io.h"
#include "tests/formats/asset_fixtures.h"

namespace mbk::test {

inline constexpr uint32_t kLutFixtureSize = 5;

// Sections in writing order: knots_n_x (0), knots_n_y (1). `ny_columns` other than 2 breaks n_y's shape.
inline std::vector<uint8_t> valid_lut_bytes(uint64_t ny_columns = 2) {
  // n_x: (x, z) rows; n_y: constant 0.25, G = 0.
  const std::vector<float> nx = {-0.5f, -1.5f, -0.2f, -0.5f, 0.0f, 0.0f, 0.1f, 0.75f, 0.5f, 1.5f};
  std::vector<float> ny = {0.25f, 0.0f};
  ny.resize(ny_columns, 0.0f);
  nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                         {"parameters", {{"size", kLutFixtureSize}}},
                         {"conventions", {{"normal_convention", "+Y"}}},
                         {"statistics", nlohmann::json::object()}};
  AssetWriter w("lut", meta);
  w.add<float>("knots_n_x", {5, 2}, nx);
  w.add<float>("knots_n_y", {1, ny_columns}, ny);
  return w.serialize();
}

// The valid fixture with element `index` of section `section` (0..1, order above) set to `value`, resealed.
inline std::vector<uint8_t> lut_with_value(size_t section, size_t index, float value) {
  std::vector<uint8_t> f = valid_lut_bytes();
  store_le<float>(&f[section_data_offset(f, section) + 4 * index], value);
  reseal_section(f, section);
  return f;
}

// The valid fixture with parameters.size replaced (resealed).
inline std::vector<uint8_t> lut_with_size(uint32_t size) {
  std::vector<uint8_t> f = valid_lut_bytes();
  const uint64_t meta_off = load_le<uint64_t>(&f[24]), meta_size = load_le<uint64_t>(&f[32]);
  nlohmann::json m = nlohmann::json::parse(std::string(f.begin() + meta_off, f.begin() + meta_off + meta_size));
  m["parameters"]["size"] = size;
  replace_metadata(f, m.dump());
  return f;
}

}  // namespace mbk::test
