// The range min/max query over a stored `rmq` table ([Wang20] Sec. 4.4, Algorithm 2): what the evaluator
// calls, reading only the asset (no dependency on the bake). Layout in formats/rmq_layout.h, codes in
// formats/rmq_quantization.h, formats/SPEC.md "Kind 3: rmq".
//
// A query is a rectangle of example texels [x, x + w) x [row, row + h), clipped to the example like the
// stored squares (x < W, row < H, w, h >= 1). It is answered EXACTLY (the returned codes are the quantized
// min/max over exactly those texels' element intervals) from stored squares of one side s:
//
//   s = 2^k, k = min(floor(log2(min(w, h))), K)      (the largest stored level not above the smaller side)
//   along x: squares at x, x + s, x + 2s, ... and the last one flush with the far edge, x + w - s
//            (ceil(w / s) of them, overlapping where needed); the same along rows.
//
// Every square lies inside the rectangle and together they cover it, so min/max over them is exact.
// Cost: ceil(w / s) * ceil(h / s) lookups. For any square of side <= 2^(K+1), i.e. every query inside a
// patch, that is 4 lookups (1 when the side is a stored power of two): O(1), as in the paper. Deviation
// [Wang20]: the paper's four same-size squares assume a square query; a rectangle wider than tall is covered
// here by a strip of ceil(w / s) x 2 squares (cost grows with the aspect ratio, bounds stay exact) rather
// than by four squares of the larger side, which would read texels outside the rectangle and loosen the
// bounds (test: RmqTable.ContainsBruteForceMinMax_NonSquareRectangles).
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <span>

#include "formats/rmq_layout.h"
#include "formats/rmq_quantization.h"

namespace mbk {

class Asset;

struct RmqCodes {
  uint32_t min_x, max_x, min_y, max_y;
};
struct RmqBounds {
  double min_x, max_x, min_y, max_y;
};

class RmqTableView {
 public:
  // `table` is the level-major code array as stored (u16 or u8 little-endian, layout.table_bytes() bytes);
  // it must outlive the view. Error(runtime_failure) when its size does not match.
  RmqTableView(const RmqLayout& layout, const std::array<RmqRange, 2>& range, std::span<const uint8_t> table);
  // A view over an asset's sections (the asset must outlive it). Error(invalid_input) naming the asset when
  // its parameters, section shapes or range are inconsistent (what `validate` reports as 13001-13003).
  static RmqTableView of(const Asset& asset);

  const RmqLayout& layout() const { return layout_; }
  const std::array<RmqRange, 2>& range() const { return range_; }

  // The stored entry: codes bounding the square [x, x + 2^level) x [row, row + 2^level) clipped.
  RmqCodes entry(uint32_t level, uint32_t x, uint32_t row) const {
    const uint8_t* p = table_.data() + layout_.entry_index(level, x, row) * 4 * layout_.code_bytes();
    if (layout_.bits == 8) return {p[0], p[1], p[2], p[3]};
    uint16_t c[4];
    std::memcpy(c, p, sizeof c);  // little-endian on every supported host (formats/byte_io.h)
    return {c[0], c[1], c[2], c[3]};
  }

  // Codes bounding the rectangle (rule above). `lookups`, when given, receives the number of squares read.
  // Error(runtime_failure) when the rectangle is empty or starts outside the example.
  RmqCodes query_codes(uint32_t x, uint32_t row, uint32_t w, uint32_t h, uint32_t* lookups = nullptr) const;
  // The same, dequantized: conservative bounds of n_x and n_y over the rectangle's elements.
  RmqBounds query(uint32_t x, uint32_t row, uint32_t w, uint32_t h) const {
    return dequantize(query_codes(x, row, w, h));
  }
  RmqBounds dequantize(const RmqCodes& codes) const;

 private:
  RmqLayout layout_;
  std::array<RmqRange, 2> range_;
  std::span<const uint8_t> table_;
};

}  // namespace mbk
