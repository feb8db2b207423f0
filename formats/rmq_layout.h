// The shape of the `rmq` asset kind's table (formats/SPEC.md, "Kind 3: rmq"), shared by the bake, the
// validator and the query: which levels exist, where each entry lives, and the parameters that fix them.
//
// For a W x H example and a patch size P = 2^K (a power of two, 1 <= P <= min(W, H), P <= 4096), levels
// k = 0..K are stored: every square side 2^k <= P. Entry (k, x, row) bounds the square
// [x, x + 2^k) x [row, row + 2^k) CLIPPED to the example, and exists for every texel, so squares touching the
// right or bottom border are stored too. The table is ONE contiguous level-major array
//   table[k][row][x][c], c = 0..3 = min_x, max_x, min_y, max_y (codes, formats/rmq_quantization.h)
// of u16 (16 bits: 8 bytes per entry, [Wang20] Sec. 5.1's packing) or u8 (8 bits: 4 bytes per entry).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/element_type.h"
#include "formats/rmq_quantization.h"

namespace mbk {

class Asset;

inline constexpr uint32_t kRmqMaxPatch = 4096;

struct RmqLayout {
  uint32_t width = 0, height = 0;  // the example, in texels
  uint32_t patch = 1;              // largest stored square side, a power of two
  uint32_t levels = 1;             // log2(patch) + 1
  uint32_t bits = 16;              // 8 or 16

  ElementType code_type() const { return bits == 8 ? ElementType::u8 : ElementType::u16; }
  uint32_t code_bytes() const { return bits / 8; }
  std::vector<uint64_t> table_shape() const { return {levels, height, width, 4}; }
  uint64_t entries_per_level() const { return uint64_t(width) * height; }
  uint64_t table_bytes() const { return entries_per_level() * levels * 4 * code_bytes(); }
  // Index of entry (level, x, row); its four codes are elements 4 * index .. 4 * index + 3.
  uint64_t entry_index(uint32_t level, uint32_t x, uint32_t row) const {
    return (uint64_t(level) * height + row) * width + x;
  }
  nlohmann::json to_parameters() const;
};

// log2(patch) + 1 for a power of two.
uint32_t rmq_levels_for_patch(uint32_t patch);

// Reads the layout from an asset's "parameters" {width, height, patch, levels, bits}; returns an empty string
// when they are complete and consistent (the rules above), else what is wrong.
std::string parse_rmq_layout(const nlohmann::json& parameters, RmqLayout& layout);

// Empty when section "table" is [levels, height, width, 4] of u16 (16 bits) or u8 (8 bits) and section "range"
// is f64 [2, 2]; else what differs.
std::string check_rmq_section_shapes(const Asset& asset, const RmqLayout& layout);

// Reads section "range" (row 0: n_x, row 1: n_y; columns lo, hi); empty when both are finite with lo <= hi.
std::string read_rmq_range(const Asset& asset, std::array<RmqRange, 2>& range);

}  // namespace mbk
