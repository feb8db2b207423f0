// Test fixtures for the `sh` kind: a small valid asset built by hand from formats/SPEC.md "Kind 4: sh"
// (independently of the bake): a 2x2 map of four known normals, order 1, whose 1x1 level 1 holds the closed-
// form means (Y00, c1 y, c1 z, c1 x); and readable corruptions of it, one per sh finding
// (tests/formats/corrupt_fixtures_test.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "formats/asset_writer.h"
#include "tests/formats/asset_fixtures.h"

namespace mbk::test {

// Sections in writing order: normals (0), level_1 (1), window (2).
inline std::vector<uint8_t> valid_sh_bytes() {
  const std::vector<float> normals = {0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0.6f, 0.8f};
  const double pi = 3.14159265358979323846, c1 = std::sqrt(3 / (4 * pi));
  // Means of the four normals: x 0.25, y 0.15, z 0.7.
  const std::vector<float> level1 = {float(0.5 / std::sqrt(pi)), float(c1 * 0.15), float(c1 * 0.7), float(c1 * 0.25)};
  nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                         {"parameters",
                          {{"width", 2},
                           {"height", 2},
                           {"levels", 2},
                           {"order", 1},
                           {"coefficients", 4},
                           {"precision", "f32"},
                           {"window", "none"}}},
                         {"conventions", {{"normal_convention", "+Y"}}},
                         {"statistics", nlohmann::json::object()}};
  AssetWriter w("sh", meta);
  w.add<float>("normals", {2, 2, 3}, normals);
  w.add<float>("level_1", {1, 1, 4}, level1);
  w.add<float>("window", {2}, std::vector<float>{1.0f, 1.0f});
  return w.serialize();
}

// The valid fixture with element `index` of section `section` (order above) set to `value`, resealed.
inline std::vector<uint8_t> sh_with_value(size_t section, size_t index, float value) {
  return with_f32_element(valid_sh_bytes(), section, index, value);
}

// The valid fixture with parameters[key] replaced (resealed).
inline std::vector<uint8_t> sh_with_parameter(const std::string& key, const nlohmann::json& value) {
  return with_parameter(valid_sh_bytes(), key, value);
}

}  // namespace mbk::test
