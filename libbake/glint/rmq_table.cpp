// Builds the RMQ table of an example normal map (see rmq_table.h).
#include "libbake/glint/rmq_table.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/glint/element_normal_bounds.h"

namespace mbk {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Per-row partial results, reduced serially in row order afterwards (deterministic whatever the threads).
struct RowRange {
  double lo_x = kInf, hi_x = -kInf, lo_y = kInf, hi_y = -kInf;
};
struct RowLeafSums {
  double half_x = 0, max_half_x = 0, half_y = 0, max_half_y = 0, slack = 0, max_slack = 0;
};

// Every texel's element reach (computed once, used by both passes over the leaves), and the range: per
// component the min of the leaf minima and the max of the leaf maxima.
std::array<RmqRange, 2> leaf_range(const NormalMap& example, std::vector<Vec2>& reach, Progress& progress) {
  std::vector<RowRange> rows(example.height);
  reach.resize(size_t(example.width) * example.height);
  parallel_for(0, example.height, [&](int64_t row) {
    RowRange& r = rows[row];
    for (uint32_t x = 0; x < example.width; ++x) {
      const size_t t = size_t(row) * example.width + x;
      reach[t] = element_normal_reach(example, x, uint32_t(row));
      const RmqBounds b = element_normal_bounds(example.texels[t], reach[t]);
      r.lo_x = std::min(r.lo_x, b.min_x), r.hi_x = std::max(r.hi_x, b.max_x);
      r.lo_y = std::min(r.lo_y, b.min_y), r.hi_y = std::max(r.hi_y, b.max_y);
    }
    progress.advance();
  });
  RowRange all;
  for (const RowRange& r : rows) {
    all.lo_x = std::min(all.lo_x, r.lo_x), all.hi_x = std::max(all.hi_x, r.hi_x);
    all.lo_y = std::min(all.lo_y, r.lo_y), all.hi_y = std::max(all.hi_y, r.hi_y);
  }
  return {RmqRange{all.lo_x, all.hi_x}, RmqRange{all.lo_y, all.hi_y}};
}

template <typename Code>
void store_entry(uint8_t* table, uint64_t index, const uint32_t (&codes)[4]) {
  const Code c[4] = {Code(codes[0]), Code(codes[1]), Code(codes[2]), Code(codes[3])};
  std::memcpy(table + index * sizeof c, c, sizeof c);
}

template <typename Code>
void load_entry(const uint8_t* table, uint64_t index, uint32_t (&codes)[4]) {
  Code c[4];
  std::memcpy(c, table + index * sizeof c, sizeof c);
  for (int i = 0; i < 4; ++i) codes[i] = c[i];
}

// Level 0: the quantized leaf intervals, and the leaf statistics.
template <typename Code>
RmqLeafStatistics quantize_leaves(const NormalMap& example, const std::vector<Vec2>& reach, RmqTable& t,
                                  Progress& progress) {
  const RmqLayout& L = t.layout;
  const RmqQuantizer quantizer[2] = {RmqQuantizer(t.range[0], L.bits), RmqQuantizer(t.range[1], L.bits)};
  std::vector<RowLeafSums> rows(L.height);
  parallel_for(0, L.height, [&](int64_t row) {
    RowLeafSums& s = rows[row];
    for (uint32_t x = 0; x < L.width; ++x) {
      const size_t texel = size_t(row) * L.width + x;
      const RmqBounds b = element_normal_bounds(example.texels[texel], reach[texel]);
      const double ends[4] = {b.min_x, b.max_x, b.min_y, b.max_y};
      uint32_t codes[4];
      for (int c = 0; c < 4; ++c) {
        const RmqQuantizer& q = quantizer[c / 2];
        codes[c] = c % 2 == 0 ? q.down(ends[c]) : q.up(ends[c]);
        const double slack = std::abs(q.value(codes[c]) - ends[c]);
        const double in_quanta = q.quantum() > 0 ? slack / q.quantum() : 0.0;
        s.slack += in_quanta;
        s.max_slack = std::max(s.max_slack, in_quanta);
      }
      store_entry<Code>(t.table.data(), L.entry_index(0, x, uint32_t(row)), codes);
      const double hx = 0.5 * (b.max_x - b.min_x), hy = 0.5 * (b.max_y - b.min_y);
      s.half_x += hx, s.max_half_x = std::max(s.max_half_x, hx);
      s.half_y += hy, s.max_half_y = std::max(s.max_half_y, hy);
    }
    progress.advance();
  });
  RmqLeafStatistics stats;
  for (const RowLeafSums& s : rows) {
    stats.mean_half_width_x += s.half_x, stats.max_half_width_x = std::max(stats.max_half_width_x, s.max_half_x);
    stats.mean_half_width_y += s.half_y, stats.max_half_width_y = std::max(stats.max_half_width_y, s.max_half_y);
    stats.mean_slack_quanta += s.slack, stats.max_slack_quanta = std::max(stats.max_slack_quanta, s.max_slack);
  }
  const double texels = double(L.entries_per_level());
  stats.mean_half_width_x /= texels;
  stats.mean_half_width_y /= texels;
  stats.mean_slack_quanta /= 4.0 * texels;
  return stats;
}

// Level k from level k - 1 ([Wang20] Algorithm 1, bottom-up): the four children at offsets 0 and 2^(k-1),
// those outside the example skipped.
template <typename Code>
void build_level(RmqTable& t, uint32_t k, Progress& progress) {
  const RmqLayout& L = t.layout;
  const uint32_t half = 1u << (k - 1);
  parallel_for(0, L.height, [&](int64_t row64) {
    const uint32_t row = uint32_t(row64);
    for (uint32_t x = 0; x < L.width; ++x) {
      uint32_t out[4] = {rmq_code_max(L.bits), 0, rmq_code_max(L.bits), 0};
      for (uint32_t dy = 0; dy <= half && row + dy < L.height; dy += half)
        for (uint32_t dx = 0; dx <= half && x + dx < L.width; dx += half) {
          uint32_t child[4];
          load_entry<Code>(t.table.data(), L.entry_index(k - 1, x + dx, row + dy), child);
          out[0] = std::min(out[0], child[0]), out[1] = std::max(out[1], child[1]);
          out[2] = std::min(out[2], child[2]), out[3] = std::max(out[3], child[3]);
        }
      store_entry<Code>(t.table.data(), L.entry_index(k, x, row), out);
    }
    progress.advance();
  });
}

template <typename Code>
void build_codes(const NormalMap& example, const std::vector<Vec2>& reach, RmqTable& t, Progress& progress) {
  t.leaf = quantize_leaves<Code>(example, reach, t, progress);
  for (uint32_t k = 1; k < t.layout.levels; ++k) build_level<Code>(t, k, progress);
}

}  // namespace

uint32_t rmq_default_patch(uint32_t width, uint32_t height) {
  const uint32_t side = std::min(width, height);
  return side == 0 ? 1 : std::min(kRmqDefaultPatch, std::bit_floor(side));
}

RmqTable build_rmq_table(const NormalMap& example, uint32_t patch, uint32_t bits, Progress& progress) {
  if (example.width == 0 || example.height == 0 || example.texels.size() != size_t(example.width) * example.height)
    throw Error(ExitCode::runtime_failure, "internal: empty or inconsistent normal map");
  RmqTable t;
  t.layout = {example.width, example.height, patch, std::has_single_bit(patch) ? rmq_levels_for_patch(patch) : 0, bits};
  if (std::string problem = parse_rmq_layout(t.layout.to_parameters(), t.layout); !problem.empty())
    throw Error(ExitCode::bad_command_line, "cannot build an rmq table: " + problem +
                                                " (patch: a power of two in [1, 4096] not above the example's "
                                                "smaller side; bits: 8 or 16)");
  progress.start("rmq table", uint64_t(example.height) * (t.layout.levels + 1));
  std::vector<Vec2> reach;
  t.range = leaf_range(example, reach, progress);
  t.table.resize(t.layout.table_bytes());  // every entry of every level is written below
  if (bits == 8)
    build_codes<uint8_t>(example, reach, t, progress);
  else
    build_codes<uint16_t>(example, reach, t, progress);
  progress.finish();
  return t;
}

}  // namespace mbk
