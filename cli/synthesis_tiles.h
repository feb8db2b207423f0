// `microbake plan --synth GRAPH`: a window of a multiscale texture too large for one `synth` command (or to spread
// over machines) planned as tiles, one `microbake synth GRAPH --window x,y,w,h ... -o TILE` per tile. A synthesized
// pixel depends on its position alone, so the tiles are exactly the pixels of the whole window ([Han08] thesis
// Sec. 5.2.2; tests/plan/synth_tiles_test.sh assembles them and compares).
// Tiles cover the window row by row from its origin, `tile` pixels a side (the last row and column narrower), and are
// named <out-dir>/<graph stem>.L<T>.<x>_<y>.<exr|png> with x, y the tile's origin at level T.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/plan_files.h"
#include "cli/synthesis_options.h"

namespace mbk::cli {

// The most tiles one plan holds.
inline constexpr uint64_t kMaxPlannedTiles = 1000000;

struct SynthesisTileRequest {
  std::filesystem::path graph;      // the analysed graph asset
  nlohmann::json technique_values;  // the "synth" schema's values (level, seed, passes)
  WindowOptions window;             // the whole window, the jitter and the correction switch
  uint32_t tile = 1024;             // tile side, pixels
  std::string extension = ".exr";   // of the tiles
  std::filesystem::path out_dir;    // where the tiles go
};

// One planned `synth` per tile. Error(bad_command_line) for a window or jitter `synth` would refuse, or more than
// kMaxPlannedTiles tiles.
std::vector<PlannedBake> plan_synthesis_tiles(const SynthesisTileRequest& request, const std::string& program);

}  // namespace mbk::cli
