// Test fixtures for the `moments` kind: a small valid 5 x 3 asset built by hand from formats/SPEC.md "Kind 8:
// moments" (level 0 = (d, d^2) about a shift of 0.25, coarser levels by the brute-force area-weighted means of
// asset_fixtures.h, independently of the bake), and readable corruptions of it, one per moments finding
// (tests/formats/corrupt_fixtures_test.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "formats/asset_writer.h"
#include "formats/byte_io.h"
#include "formats/mip_levels.h"
#include "tests/formats/asset_fixtures.h"

namespace mbk::test {

inline std::vector<uint8_t> moments_bytes(const nlohmann::json& parameters) {
  constexpr uint32_t W = 5, H = 3;
  std::vector<float> level0;
  for (uint32_t i = 0; i < W * H; ++i) {
    const float d = float(0.5 + 0.4 * std::sin(1.3 * i) - 0.25);
    level0.push_back(d);
    level0.push_back(float(double(d) * double(d)));
  }
  const auto levels = brute_force_pyramid(level0, W, H, 2);
  const auto sizes = mip_level_sizes(W, H);
  nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                         {"parameters", parameters},
                         {"conventions", nlohmann::json::object()},
                         {"statistics", nlohmann::json::object()}};
  AssetWriter w("moments", meta);
  for (size_t k = 0; k < levels.size(); ++k)
    w.add<float>("level_" + std::to_string(k), {sizes[k].height, sizes[k].width, 2}, levels[k]);
  return w.serialize();
}

inline nlohmann::json moments_fixture_parameters() {
  return {{"width", 5}, {"height", 3}, {"levels", 3}, {"shift", 0.25}};
}

inline std::vector<uint8_t> valid_moments_bytes() { return moments_bytes(moments_fixture_parameters()); }

inline std::vector<uint8_t> moments_with_parameter(const std::string& key, const nlohmann::json& value) {
  nlohmann::json p = moments_fixture_parameters();
  p[key] = value;
  return moments_bytes(p);
}

// The valid fixture with element `index` of level `level` changed by `change(old)`, resealed.
template <typename F>
std::vector<uint8_t> moments_with_element(size_t level, size_t index, F change) {
  std::vector<uint8_t> f = valid_moments_bytes();
  const size_t at = section_data_offset(f, level) + 4 * index;
  store_le<float>(&f[at], change(load_le<float>(&f[at])));
  reseal_section(f, level);
  return f;
}

}  // namespace mbk::test
