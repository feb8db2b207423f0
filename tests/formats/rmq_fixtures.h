// Test fixtures for the `rmq` kind: a small valid asset built by hand (arbitrary ordered leaf codes, coarser
// levels by brute force over each clipped square, independently of the bake), and readable corruptions of
// it, one per rmq finding (tests/formats/corrupt_fixtures_test.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "formats/asset_writer.h"
#include "formats/byte_io.h"
#include "formats/rmq_layout.h"
#include "libbake/core/hash.h"
#include "tests/formats/asset_fixtures.h"

namespace mbk::test {

// A 5 x 3 example, patch 2 (levels 0 and 1), 16 bits: sections "table" (index 0) and "range" (index 1).
inline RmqLayout rmq_fixture_layout() { return {5, 3, 2, 2, 16}; }

inline std::vector<uint16_t> rmq_fixture_codes(const RmqLayout& L) {
  std::vector<uint16_t> t(L.table_bytes() / 2);
  for (uint32_t row = 0; row < L.height; ++row)
    for (uint32_t x = 0; x < L.width; ++x)
      for (int c = 0; c < 4; c += 2) {
        // Leaf intervals of width >= 1000 codes, away from both ends (room for the corruptions below).
        const uint16_t lo = uint16_t(1000 + hash3(x, row, c) % 30000);
        t[L.entry_index(0, x, row) * 4 + c] = lo;
        t[L.entry_index(0, x, row) * 4 + c + 1] = uint16_t(lo + 1000 + hash3(x, row, c + 1) % 30000);
      }
  for (uint32_t k = 1; k < L.levels; ++k)
    for (uint32_t row = 0; row < L.height; ++row)
      for (uint32_t x = 0; x < L.width; ++x) {
        uint16_t e[4] = {65535, 0, 65535, 0};
        for (uint32_t r = row; r < std::min(row + (1u << k), L.height); ++r)
          for (uint32_t c = x; c < std::min(x + (1u << k), L.width); ++c) {
            const uint16_t* leaf = &t[L.entry_index(0, c, r) * 4];
            e[0] = std::min(e[0], leaf[0]), e[1] = std::max(e[1], leaf[1]);
            e[2] = std::min(e[2], leaf[2]), e[3] = std::max(e[3], leaf[3]);
          }
        std::copy(e, e + 4, &t[L.entry_index(k, x, row) * 4]);
      }
  return t;
}

inline std::vector<uint8_t> valid_rmq_bytes() {
  const RmqLayout L = rmq_fixture_layout();
  nlohmann::json meta = {{"inputs", nlohmann::json::array()},
                         {"parameters", L.to_parameters()},
                         {"conventions", {{"normal_convention", "+Y"}}},
                         {"statistics", nlohmann::json::object()}};
  AssetWriter w("rmq", meta);
  w.add<uint16_t>("table", L.table_shape(), rmq_fixture_codes(L));
  w.add<double>("range", {2, 2}, std::vector<double>{-0.5, 0.75, -0.25, 0.5});
  return w.serialize();
}

// The valid fixture with one metadata parameter replaced.
inline std::vector<uint8_t> rmq_with_parameter(const std::string& key, const nlohmann::json& value) {
  std::vector<uint8_t> f = valid_rmq_bytes();
  const uint64_t off = load_le<uint64_t>(&f[24]), size = load_le<uint64_t>(&f[32]);
  nlohmann::json meta = nlohmann::json::parse(f.begin() + off, f.begin() + off + size);
  meta["parameters"][key] = value;
  replace_metadata(f, meta.dump());
  return f;
}

// The valid fixture with code c of entry (level, x, row) changed by `change`, checksums resealed.
template <typename Change>
std::vector<uint8_t> rmq_with_code(uint32_t level, uint32_t x, uint32_t row, int c, Change change) {
  std::vector<uint8_t> f = valid_rmq_bytes();
  const RmqLayout L = rmq_fixture_layout();
  const uint64_t at = section_data_offset(f, 0) + (L.entry_index(level, x, row) * 4 + c) * 2;
  store_le<uint16_t>(&f[at], change(load_le<uint16_t>(&f[at]), load_le<uint16_t>(&f[at + (c % 2 ? -2 : 2)])));
  reseal_section(f, 0);
  return f;
}

// The valid fixture with range entry i (0 lo_x, 1 hi_x, 2 lo_y, 3 hi_y) replaced, checksums resealed.
inline std::vector<uint8_t> rmq_with_range_value(int i, double value) {
  std::vector<uint8_t> f = valid_rmq_bytes();
  store_le<double>(&f[section_data_offset(f, 1) + 8 * i], value);
  reseal_section(f, 1);
  return f;
}

}  // namespace mbk::test
