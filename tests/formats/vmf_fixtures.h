// Test fixtures for the `vmf` kind: a small valid asset built by hand from formats/SPEC.md "Kind 5: vmf"
// (independently of EM): a 2x2 map, two normals +z and two (0.6, 0, 0.8), J = 2, one feature channel. Level 0
// holds (1, n) in slot 0 per texel; level 1 holds the exact two-lobe fit (alpha 0.5 each, |r| = 1), whose first
// moment is the mean normal; and readable corruptions of it, one per vmf finding
// (tests/formats/corrupt_fixtures_test.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/asset_writer.h"
#include "tests/formats/asset_fixtures.h"

namespace mbk::test {

// Sections in writing order: level_0 (0), features_0 (1), level_1 (2), features_1 (3).
inline std::vector<uint8_t> valid_vmf_bytes() {
  // Texels (0,0) and (1,0): +z with feature 0.2; (0,1) and (1,1): (0.6, 0, 0.8) with feature 0.6.
  const std::vector<float> level0 = {1, 0,    0, 1,    0, 0, 0, 0, 1, 0,    0, 1,    0, 0, 0, 0,
                                     1, 0.6f, 0, 0.8f, 0, 0, 0, 0, 1, 0.6f, 0, 0.8f, 0, 0, 0, 0};
  const std::vector<float> features0 = {0.2f, 0, 0.2f, 0, 0.6f, 0, 0.6f, 0};
  const std::vector<float> level1 = {0.5f, 0, 0, 0.5f, 0.5f, 0.3f, 0, 0.4f};
  const std::vector<float> features1 = {0.1f, 0.3f};
  nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                         {"parameters",
                          {{"width", 2},
                           {"height", 2},
                           {"levels", 2},
                           {"lobes", 2},
                           {"align", 0.0},
                           {"tolerance", 1e-6},
                           {"max_iterations", 100},
                           {"kappa_max", 1e6},
                           {"feature_channels", 1}}},
                         {"conventions", {{"normal_convention", "+Y"}}},
                         {"statistics", nlohmann::json::object()}};
  AssetWriter w("vmf", meta);
  w.add<float>("level_0", {2, 2, 2, 4}, level0);
  w.add<float>("features_0", {2, 2, 2, 1}, features0);
  w.add<float>("level_1", {1, 1, 2, 4}, level1);
  w.add<float>("features_1", {1, 1, 2, 1}, features1);
  return w.serialize();
}

// The valid fixture with element `index` of section `section` (order above) set to `value`, resealed.
inline std::vector<uint8_t> vmf_with_value(size_t section, size_t index, float value) {
  return with_f32_element(valid_vmf_bytes(), section, index, value);
}

// The valid fixture with parameters[key] replaced (resealed).
inline std::vector<uint8_t> vmf_with_parameter(const std::string& key, const nlohmann::json& value) {
  return with_parameter(valid_vmf_bytes(), key, value);
}

}  // namespace mbk::test
