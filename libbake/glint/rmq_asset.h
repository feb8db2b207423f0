// The `rmq` asset kind (formats/kind_rmq.cpp, formats/SPEC.md "Kind 3: rmq"): an example normal map's RMQ
// table (rmq_table.h) with its quantization range, parameters, conventions and statistics.
#pragma once

#include <cstdint>

#include "formats/asset_writer.h"
#include "libbake/core/progress.h"
#include "libbake/image/normal_map.h"

namespace mbk {

// Sections "table" (u16 or u8 [levels, height, width, 4]) and "range" (f64 [2, 2]); metadata "parameters"
// {width, height, patch, levels, bits}; "conventions": the normal-map conventions plus the table's layout,
// leaf rule, quantization and borders; "statistics": levels_stored, square_sides, bytes_per_entry,
// bytes_per_level, table_bytes, paper_table_bytes (8 bytes per entry at the same number of levels, [Wang20]
// Sec. 5.1), quantum {x, y}, leaf_half_width {mean_x, max_x, mean_y, max_y}, leaf_slack_quanta {mean, max}.
// Bakes the range and level 0 (with the progress); the table's levels are produced while the writer writes
// (AssetWriter::add_produced), so the bake never holds the whole table. The writer does not refer to `input`.
AssetWriter bake_rmq_asset(const LoadedNormalMap& input, uint32_t patch, uint32_t bits, Progress& progress);

}  // namespace mbk
