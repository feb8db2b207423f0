// Builds the RMQ table of an example normal map (see rmq_table.h).
#include "libbake/glint/rmq_table.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <optional>
#include <unordered_map>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/glint/element_normal_bounds.h"
#include "libbake/glint/rmq_atom_range.h"

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

// A row's leaf intervals, [n - reach, n + reach] per component (element_normal_bounds.h), computed row by row
// from the row's reaches (element_normal_reach_row) into per-thread scratch.
struct LeafRow {
  std::vector<double> reach_x, reach_y;
  void compute(const NormalMap& example, uint32_t row) {
    reach_x.resize(example.width), reach_y.resize(example.width);
    element_normal_reach_row(example, row, reach_x.data(), reach_y.data());
  }
};

// Counts of the values of one component's degenerate leaves (reach 0: the texel and its 3 x 3 neighbours share
// the value), the flat ground's candidates; consecutive texels of a plateau hit the last entry.
struct PlateauCounts {
  std::unordered_map<double, uint64_t> count;
  double last = std::numeric_limits<double>::quiet_NaN();
  uint64_t* last_count = nullptr;
  void add(double v) {
    if (v != last || !last_count) last = v, last_count = &count[v];
    ++*last_count;
  }
  void merge(const PlateauCounts& other) {
    for (const auto& [v, c] : other.count) count[v] += c;
  }
  // The most common value (the smaller on ties: the same whatever the map's order), if any.
  std::optional<double> most_common() const {
    std::optional<double> best;
    uint64_t best_count = 0;
    for (const auto& [v, c] : count)
      if (c > best_count || (c == best_count && best && v < *best)) best = v, best_count = c;
    return best;
  }
};

// The range: per component the min of the leaf minima and the max of the leaf maxima, widened so that the most
// common degenerate leaf (the flat ground) is a code (rmq_atom_range.h).
std::array<RmqRange, 2> leaf_range(const NormalMap& example, uint32_t bits, Progress& progress) {
  std::vector<RowRange> rows(example.height);
  std::vector<std::array<PlateauCounts, 2>> plateaus(example.height);
  parallel_for(0, example.height, [&](int64_t row) {
    thread_local LeafRow leaf;
    leaf.compute(example, uint32_t(row));
    const Vec3f* n = &example.texels[size_t(row) * example.width];
    RowRange& r = rows[size_t(row)];
    std::array<PlateauCounts, 2>& plateau = plateaus[size_t(row)];
    for (uint32_t x = 0; x < example.width; ++x) {
      const double nx = n[x].x(), ny = n[x].y();
      r.lo_x = std::min(r.lo_x, nx - leaf.reach_x[x]), r.hi_x = std::max(r.hi_x, nx + leaf.reach_x[x]);
      r.lo_y = std::min(r.lo_y, ny - leaf.reach_y[x]), r.hi_y = std::max(r.hi_y, ny + leaf.reach_y[x]);
      if (leaf.reach_x[x] == 0.0) plateau[0].add(nx);
      if (leaf.reach_y[x] == 0.0) plateau[1].add(ny);
    }
    progress.advance();
  });
  RowRange all;
  std::array<PlateauCounts, 2> plateau;
  for (size_t row = 0; row < rows.size(); ++row) {
    const RowRange& r = rows[row];
    all.lo_x = std::min(all.lo_x, r.lo_x), all.hi_x = std::max(all.hi_x, r.hi_x);
    all.lo_y = std::min(all.lo_y, r.lo_y), all.hi_y = std::max(all.hi_y, r.hi_y);
    for (int c = 0; c < 2; ++c) plateau[c].merge(plateaus[row][c]);
  }
  return {rmq_range_with_exact_value(RmqRange{all.lo_x, all.hi_x}, plateau[0].most_common(), bits),
          rmq_range_with_exact_value(RmqRange{all.lo_y, all.hi_y}, plateau[1].most_common(), bits)};
}

// Level 0: the quantized leaf intervals, and the leaf statistics.
template <typename Code>
RmqLeafStatistics quantize_leaves(const NormalMap& example, RmqLeafLevel& t, Progress& progress) {
  const RmqLayout& L = t.layout;
  const RmqQuantizer quantizer[2] = {RmqQuantizer(t.range[0], L.bits), RmqQuantizer(t.range[1], L.bits)};
  std::vector<RowLeafSums> rows(L.height);
  parallel_for(0, L.height, [&](int64_t row) {
    thread_local LeafRow leaf;
    leaf.compute(example, uint32_t(row));
    const Vec3f* n = &example.texels[size_t(row) * L.width];
    Code* out = reinterpret_cast<Code*>(t.codes.data()) + 4 * L.entry_index(0, 0, uint32_t(row));
    RowLeafSums s;  // a local, so that the sums stay in registers
    for (uint32_t x = 0; x < L.width; ++x) {
      const double ends[4] = {n[x].x() - leaf.reach_x[x], n[x].x() + leaf.reach_x[x], n[x].y() - leaf.reach_y[x],
                              n[x].y() + leaf.reach_y[x]};
      for (int c = 0; c < 4; ++c) {
        const RmqQuantizer& q = quantizer[c / 2];
        const uint32_t code = c % 2 == 0 ? q.down(ends[c]) : q.up(ends[c]);
        out[4 * x + c] = Code(code);
        const double slack = std::abs(q.value(code) - ends[c]);
        const double in_quanta = q.quantum() > 0 ? slack / q.quantum() : 0.0;
        s.slack += in_quanta;
        s.max_slack = std::max(s.max_slack, in_quanta);
      }
      const double hx = 0.5 * (ends[1] - ends[0]), hy = 0.5 * (ends[3] - ends[2]);
      s.half_x += hx, s.max_half_x = std::max(s.max_half_x, hx);
      s.half_y += hy, s.max_half_y = std::max(s.max_half_y, hy);
    }
    rows[size_t(row)] = s;
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

// Level k from level k - 1 ([Wang20] Algorithm 1, bottom-up), one pass over the rows: entry (x, row) combines the
// children (x, row), (x + h, row), (x, row + h), (x + h, row + h), h = 2^(k-1), those outside the example
// skipped (a child row below the example is replaced by the row itself: min and max are idempotent). Codes run
// min_x, max_x, min_y, max_y: even codes take the smallest, odd the largest; loops over a row's codes, so that
// the compiler vectorises them.
template <typename Code>
void build_level(const RmqLayout& L, uint32_t k, const Code* previous, Code* out_level) {
  const uint32_t half = 1u << (k - 1);
  const size_t row_codes = 4 * size_t(L.width), shift = 4 * size_t(std::min(half, L.width));
  parallel_for(0, L.height, [&](int64_t row64) {
    const uint32_t row = uint32_t(row64);
    const Code* top = previous + row * row_codes;
    const Code* bottom = row + half < L.height ? top + half * row_codes : top;
    Code* out = out_level + row * row_codes;
    size_t i = 0;
    for (; i < row_codes - shift; i += 2) {  // the four children inside the example
      out[i] = std::min({top[i], bottom[i], top[i + shift], bottom[i + shift]});
      out[i + 1] = std::max({top[i + 1], bottom[i + 1], top[i + 1 + shift], bottom[i + 1 + shift]});
    }
    for (; i < row_codes; i += 2) {  // x + h outside the example
      out[i] = std::min(top[i], bottom[i]);
      out[i + 1] = std::max(top[i + 1], bottom[i + 1]);
    }
  });
}

template <typename Code>
void for_each_level(const RmqLeafLevel& leaves,
                    const std::function<void(uint32_t k, std::span<const uint8_t> codes)>& level) {
  const RmqLayout& L = leaves.layout;
  const size_t level_bytes = leaves.codes.size();
  level(0, leaves.codes);
  UninitializedVector<uint8_t> built[2];
  const Code* previous = reinterpret_cast<const Code*>(leaves.codes.data());
  for (uint32_t k = 1; k < L.levels; ++k) {
    UninitializedVector<uint8_t>& out = built[k % 2];
    out.resize(level_bytes);
    build_level<Code>(L, k, previous, reinterpret_cast<Code*>(out.data()));
    level(k, out);
    previous = reinterpret_cast<const Code*>(out.data());
  }
}

}  // namespace

uint32_t rmq_default_patch(uint32_t width, uint32_t height) {
  const uint32_t side = std::min(width, height);
  return side == 0 ? 1 : std::min(kRmqDefaultPatch, std::bit_floor(side));
}

RmqLeafLevel build_rmq_leaf_level(const NormalMap& example, uint32_t patch, uint32_t bits, Progress& progress) {
  if (example.width == 0 || example.height == 0 || example.texels.size() != size_t(example.width) * example.height)
    throw Error(ExitCode::runtime_failure, "internal: empty or inconsistent normal map");
  RmqLeafLevel t;
  t.layout = {example.width, example.height, patch, std::has_single_bit(patch) ? rmq_levels_for_patch(patch) : 0, bits};
  if (std::string problem = parse_rmq_layout(t.layout.to_parameters(), t.layout); !problem.empty())
    throw Error(ExitCode::bad_command_line, "cannot build an rmq table: " + problem +
                                                " (patch: a power of two in [1, 4096] not above the example's "
                                                "smaller side; bits: 8 or 16)");
  progress.start("rmq leaves", 2 * uint64_t(example.height));
  t.range = leaf_range(example, bits, progress);
  t.codes.resize(t.layout.entries_per_level() * 4 * t.layout.code_bytes());  // every entry written below
  t.leaf = bits == 8 ? quantize_leaves<uint8_t>(example, t, progress) : quantize_leaves<uint16_t>(example, t, progress);
  progress.finish();
  return t;
}

void for_each_rmq_level(const RmqLeafLevel& leaves,
                        const std::function<void(uint32_t k, std::span<const uint8_t> codes)>& level) {
  if (leaves.layout.bits == 8)
    for_each_level<uint8_t>(leaves, level);
  else
    for_each_level<uint16_t>(leaves, level);
}

RmqTable build_rmq_table(const NormalMap& example, uint32_t patch, uint32_t bits, Progress& progress) {
  RmqLeafLevel leaves = build_rmq_leaf_level(example, patch, bits, progress);
  RmqTable t{leaves.layout, leaves.range, {}, leaves.leaf};
  t.table.resize(t.layout.table_bytes());  // every level is copied in below
  for_each_rmq_level(leaves, [&](uint32_t k, std::span<const uint8_t> codes) {
    std::memcpy(t.table.data() + k * codes.size(), codes.data(), codes.size());
  });
  return t;
}

}  // namespace mbk
