// The O(1) range query over a stored `rmq` table (see rmq_query.h).
#include "formats/rmq_query.h"

#include <algorithm>
#include <bit>
#include <string>

#include "formats/asset.h"
#include "formats/error.h"

namespace mbk {

RmqTableView::RmqTableView(const RmqLayout& layout, const std::array<RmqRange, 2>& range,
                           std::span<const uint8_t> table)
    : layout_(layout), range_(range), table_(table) {
  if (table.size() != layout.table_bytes())
    throw Error(ExitCode::runtime_failure, "internal: rmq table holds " + std::to_string(table.size()) +
                                               " bytes, its layout needs " + std::to_string(layout.table_bytes()));
}

RmqTableView RmqTableView::of(const Asset& asset) {
  RmqLayout layout;
  std::string problem = parse_rmq_layout(asset.metadata()["parameters"], layout);
  if (problem.empty()) problem = check_rmq_section_shapes(asset, layout);
  std::array<RmqRange, 2> range;
  if (problem.empty()) problem = read_rmq_range(asset, range);
  if (!problem.empty()) throw Error(ExitCode::invalid_input, "not a usable rmq asset: " + problem, asset.where());
  return RmqTableView(layout, range, asset.bytes_of(asset.section("table")));
}

RmqCodes RmqTableView::query_codes(uint32_t x, uint32_t row, uint32_t w, uint32_t h, uint32_t* lookups) const {
  if (x >= layout_.width || row >= layout_.height || w == 0 || h == 0)
    throw Error(ExitCode::runtime_failure, "internal: rmq query [" + std::to_string(x) + ", +" + std::to_string(w) +
                                               ") x [" + std::to_string(row) + ", +" + std::to_string(h) +
                                               ") is empty or outside the " + std::to_string(layout_.width) + "x" +
                                               std::to_string(layout_.height) + " example");
  // Clip to the example, as the stored squares are.
  w = std::min(w, layout_.width - x);
  h = std::min(h, layout_.height - row);
  const uint32_t level = std::min<uint32_t>(std::bit_width(std::min(w, h)) - 1, layout_.levels - 1);
  const uint32_t s = 1u << level;
  const uint32_t last_x = x + w - s, last_row = row + h - s;
  RmqCodes out{rmq_code_max(layout_.bits), 0, rmq_code_max(layout_.bits), 0};
  uint32_t count = 0;
  for (uint32_t r = row;; r = std::min(r + s, last_row)) {
    for (uint32_t c = x;; c = std::min(c + s, last_x)) {
      const RmqCodes e = entry(level, c, r);
      out.min_x = std::min(out.min_x, e.min_x);
      out.max_x = std::max(out.max_x, e.max_x);
      out.min_y = std::min(out.min_y, e.min_y);
      out.max_y = std::max(out.max_y, e.max_y);
      ++count;
      if (c == last_x) break;
    }
    if (r == last_row) break;
  }
  if (lookups) *lookups = count;
  return out;
}

RmqBounds RmqTableView::dequantize(const RmqCodes& codes) const {
  const uint32_t bits = layout_.bits;
  return {rmq_dequantize(codes.min_x, range_[0], bits), rmq_dequantize(codes.max_x, range_[0], bits),
          rmq_dequantize(codes.min_y, range_[1], bits), rmq_dequantize(codes.max_y, range_[1], bits)};
}

}  // namespace mbk
