// Test fixtures for the `lut` kind: a small valid asset built by hand from the lookup convention of
// formats/SPEC.md "Kind 2: lut" (independently of the bake): channel n_x a non-linear monotone pair of 5-sample
// tables, channel n_y a constant channel; and readable corruptions of it, one per lut finding
// (tests/formats/corrupt_fixtures_test.cpp).
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

// Sections in writing order: domains (0), forward (1), forward_slope (2), inverse (3), inverse_slope (4).
inline std::vector<uint8_t> valid_lut_bytes() {
  constexpr uint32_t M = kLutFixtureSize;
  // n_x: forward on [-0.5, 0.5] runs from z_lo = -1.5 to z_hi = 1.5; inverse on [-1.5, 1.5] from -0.5 to 0.5.
  // n_y: constant 0.25: empty domains, G = 0, G^-1 = 0.25.
  const std::vector<float> domains = {-0.5f, 0.5f, -1.5f, 1.5f, 0.25f, 0.25f, 0.0f, 0.0f};
  const std::vector<float> forward = {-1.5f, -0.5f, 0.0f, 0.75f, 1.5f, 0, 0, 0, 0, 0};
  const std::vector<float> inverse = {-0.5f, -0.2f, 0.0f, 0.1f, 0.5f, 0.25f, 0.25f, 0.25f, 0.25f, 0.25f};
  // Slope j = (v_{j+1} - v_j) / ((hi - lo) / (M - 1)); 0 for an empty domain.
  auto slopes = [](const std::vector<float>& v, double lo, double hi) {
    std::vector<float> s;
    for (uint32_t j = 0; j + 1 < M; ++j) s.push_back(float((double(v[j + 1]) - double(v[j])) / ((hi - lo) / (M - 1))));
    for (uint32_t j = 0; j + 1 < M; ++j) s.push_back(0.0f);
    return s;
  };
  nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                         {"parameters", {{"size", M}}},
                         {"conventions", {{"normal_convention", "+Y"}}},
                         {"statistics", nlohmann::json::object()}};
  AssetWriter w("lut", meta);
  w.add<float>("domains", {2, 4}, domains);
  w.add<float>("forward", {2, M}, forward);
  w.add<float>("forward_slope", {2, M - 1}, slopes(forward, -0.5, 0.5));
  w.add<float>("inverse", {2, M}, inverse);
  w.add<float>("inverse_slope", {2, M - 1}, slopes(inverse, -1.5, 1.5));
  return w.serialize();
}

// The valid fixture with element `index` of section `section` (0..4, order above) set to `value`, resealed.
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
