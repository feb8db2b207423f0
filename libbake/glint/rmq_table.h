// The RMQ table of an example normal map ([Wang20] Sec. 4.4, 5.1, Algorithm 1): for every texel (x, row) and
// every level k = 0..K (2^K = the patch size), the min and max of n_x and n_y over the square
// [x, x + 2^k) x [row, row + 2^k) clipped to the example, quantized conservatively into ONE level-major
// array (layout: formats/rmq_layout.h; codes: formats/rmq_quantization.h; query: formats/rmq_query.h).
//
// Build, one pass over the rows per level plus one for the range (each row writes only its own entries:
// identical bytes whatever the thread count):
// 1. The range: per component, [lo, hi] = [min of the leaf minima, max of the leaf maxima], where a texel's
//    leaf interval is its element's reach (element_normal_bounds.h), in double, a row at a time
//    (element_normal_reach_row: each texel difference once per row, nothing kept per texel), widened so that
//    the flat ground - the most common value among leaves of zero reach - is exactly a code
//    (rmq_atom_range.h: why).
// 2. Level 0: each row's leaf intervals again, quantized, min down and max up (one quantum at most, in the safe
//    direction), straight into level 0 (allocated, not zero-filled: every entry is written once).
// 3. Level k + 1 from level k (Algorithm 1's recursion, bottom-up): entry (k+1, x, row) is the min/max of the
//    level-k entries at x or x + 2^k and row or row + 2^k, children outside the example skipped, so squares
//    touching the border are the clipped squares.
// The leaf reach is computed twice (passes 1 and 2) rather than kept: keeping it costs 16 bytes a texel (64 MiB
// at 2048^2, 30% of the table) to save one reach pass, about a tenth of the bake (perf, 2048^2).
// Deviation [Wang20]: the recursion runs on the quantized codes, not on doubles quantized afterwards. Both
// quantizers are monotone, so min/max commute with them and the codes are IDENTICAL to quantizing the exact
// double min/max of every square (test: RmqTable.EveryStoredSquareIsTheQuantizedClippedBruteForce), while
// the bake holds nothing but the codes and the leaf reaches (no double copy of 7 levels: 128 MiB per level at
// 2048^2). A bake hands each level to the file as it is built (for_each_rmq_level), so it holds level 0 and two
// more levels, not the whole table (3/7 of it at the default patch).
// Deviation [Wang20]: the paper stores levels 1..K and reads a texel's own normal at level 0; here level 0 is
// stored because the leaf is the element's interval (Jacobian and cut-off), not the bare normal.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "formats/rmq_layout.h"
#include "formats/rmq_query.h"
#include "libbake/core/progress.h"
#include "libbake/core/uninitialized_vector.h"
#include "libbake/image/normal_map.h"

namespace mbk {

// The default patch: 64 texels, K = 6, 7 levels (0..6), which costs a 512 x 512 example exactly the 14 MiB
// that [Wang20] Sec. 5.1 reports (7 levels x 512^2 entries x 8 bytes).
inline constexpr uint32_t kRmqDefaultPatch = 64;
// kRmqDefaultPatch, or the largest power of two not above min(width, height) for smaller examples (a patch
// must fit inside the example).
uint32_t rmq_default_patch(uint32_t width, uint32_t height);

// Figures over the leaf intervals (level 0), recorded in the asset's statistics. Every stored bound at any
// level is one leaf bound quantized, so the slack of any query result is the slack of one leaf bound.
struct RmqLeafStatistics {
  double mean_half_width_x = 0, max_half_width_x = 0;  // element reach (|J_x.| * 3 sigma_h), normal units
  double mean_half_width_y = 0, max_half_width_y = 0;
  double mean_slack_quanta = 0, max_slack_quanta = 0;  // |stored bound - exact bound| / quantum, over all bounds
};

// The first two passes: the quantization range, level 0 (the quantized leaf intervals) and their statistics. All a
// bake needs before the file's layout is known (rmq_asset.h); levels 1..K follow from level 0 alone.
struct RmqLeafLevel {
  RmqLayout layout;
  std::array<RmqRange, 2> range;       // n_x, n_y
  UninitializedVector<uint8_t> codes;  // level 0 exactly as stored (u16 little-endian or u8)
  RmqLeafStatistics leaf;
};

// patch: a power of two in [1, 4096], not above min(width, height); bits: 8 or 16. Error(bad_command_line)
// otherwise, naming the rule.
RmqLeafLevel build_rmq_leaf_level(const NormalMap& example, uint32_t patch, uint32_t bits, Progress& progress);

// Levels 0..K in order, handed to `level(k, codes)` (the level's bytes exactly as stored): level k + 1 is built
// from level k, so no more than two levels beyond level 0 are in memory at a time. Silent: each level is one
// pass of min/max over the codes, a small part of the bake (the leaf reach dominates).
void for_each_rmq_level(const RmqLeafLevel& leaves,
                        const std::function<void(uint32_t k, std::span<const uint8_t> codes)>& level);

// The whole table in memory, for queries (glint evaluation, tests).
struct RmqTable {
  RmqLayout layout;
  std::array<RmqRange, 2> range;       // n_x, n_y
  UninitializedVector<uint8_t> table;  // the level-major code array exactly as stored (u16 little-endian or u8)
  RmqLeafStatistics leaf;

  RmqTableView view() const { return RmqTableView(layout, range, table); }
};

// build_rmq_leaf_level, then every level into one array.
RmqTable build_rmq_table(const NormalMap& example, uint32_t patch, uint32_t bits, Progress& progress);

}  // namespace mbk
