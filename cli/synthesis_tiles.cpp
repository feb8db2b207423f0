// Synthesis windows planned as tiles (see synthesis_tiles.h).
#include "cli/synthesis_tiles.h"

#include <algorithm>

#include "formats/error.h"
#include "libbake/scene/asset_command.h"

namespace mbk::cli {

std::vector<PlannedBake> plan_synthesis_tiles(const SynthesisTileRequest& request, const std::string& program) {
  constexpr uint64_t kMaxPlannedSide = uint64_t(1) << 32;
  const WindowRectangle window = parse_window(request.window.window, kMaxPlannedSide);
  (void)parse_jitter(request.window.jitter);  // refused here rather than in every tile
  const uint64_t columns = (window.width + request.tile - 1) / request.tile;
  const uint64_t rows = (window.height + request.tile - 1) / request.tile;
  // Each factor is checked first: 2^32 x 2^32 tiles of one pixel would overflow the product.
  if (columns > kMaxPlannedTiles || rows > kMaxPlannedTiles || columns * rows > kMaxPlannedTiles)
    throw Error(ExitCode::bad_command_line,
                "the window would be " + std::to_string(columns) + " x " + std::to_string(rows) + " tiles; at most " +
                    std::to_string(kMaxPlannedTiles) + " (use a larger --tile)",
                "--tile");
  if (window.x > kMaxSynthesisCoordinate - int64_t(window.width) ||
      window.y > kMaxSynthesisCoordinate - int64_t(window.height))
    throw Error(ExitCode::bad_command_line, "the window must lie within +-2^62 pixels", "--window");

  AssetRecipe recipe;
  recipe.kind = "synth";
  recipe.inputs.push_back(BakeInput{request.graph, std::nullopt, ""});
  recipe.technique_values = request.technique_values;
  const std::string level = request.technique_values.at("level").dump();
  const std::string stem = request.graph.stem().string();

  std::vector<PlannedBake> tiles;
  tiles.reserve(columns * rows);
  for (uint64_t row = 0; row < rows; ++row) {
    for (uint64_t column = 0; column < columns; ++column) {
      const int64_t x = window.x + int64_t(column * request.tile);
      const int64_t y = window.y + int64_t(row * request.tile);
      const uint64_t width = std::min<uint64_t>(request.tile, window.width - column * request.tile);
      const uint64_t height = std::min<uint64_t>(request.tile, window.height - row * request.tile);
      const std::string origin = std::to_string(x) + "_" + std::to_string(y);
      const std::string rectangle =
          std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(width) + "," + std::to_string(height);
      std::vector<std::string> extra;
      append_option(extra, "--window", rectangle);
      append_option(extra, "--jitter", request.window.jitter);
      if (request.window.no_correction) extra.push_back("--no-correction");
      PlannedBake tile;
      tile.output = request.out_dir / (stem + ".L" + level + "." + origin + request.extension);
      tile.inputs = {request.graph};
      tile.command = asset_command(recipe, tile.output, program, extra);
      tile.description = "synth " + tile.output.string() + " (" + std::to_string(width) + "x" + std::to_string(height) +
                         " at " + std::to_string(x) + "," + std::to_string(y) + ")";
      tiles.push_back(std::move(tile));
    }
  }
  return tiles;
}

}  // namespace mbk::cli
