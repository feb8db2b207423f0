// Baking the crease asset (see crease_asset.h).
#include "libbake/crease/crease_asset.h"

#include <cmath>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/core/release_free_memory.h"
#include "libbake/crease/gradient_smoothing.h"

namespace mbk {

nlohmann::json CurvesRecord::to_json() const {
  return {{"path", path}, {"content_hash", content_hash}, {"bytes", bytes}, {"curves", curves}, {"segments", segments}};
}

CurvesRecord curves_record(const std::filesystem::path& path, const CurveSet& curves) {
  CurvesRecord record;
  record.path = path.string();
  record.content_hash = file_content_hash(path);
  record.bytes = std::filesystem::file_size(path);
  record.curves = curves.curves.size();
  record.segments = curve_segments(curves).size();
  return record;
}

BakedCrease bake_crease(NormalMap map, const CurveSet& curves, const CreaseBakeOptions& options, Progress& progress) {
  if (!(options.band > 0.0 && options.band <= 1e6))
    throw Error(ExitCode::bad_command_line, "--band must be in (0, 1e6] texels");
  if (options.smooth_iterations > kCreaseMaxSmoothIterations)
    throw Error(ExitCode::bad_command_line,
                "--smooth-iterations must be at most " + std::to_string(kCreaseMaxSmoothIterations));
  if (map.texels.empty()) throw Error(ExitCode::runtime_failure, "internal: empty normal map");
  BakedCrease baked;
  CreaseField& f = baked.field;
  f.allocate_lattice(map.width, map.height);  // the distance maps are sized when made (crease_distance.h)
  parallel_for(0, map.height, [&](int64_t row) {
    for (size_t k = size_t(row) * map.width; k < size_t(row + 1) * map.width; ++k)
      for (int c = 0; c < 3; ++c) f.normals[3 * k + size_t(c)] = map.texels[k][c];
  });
  decltype(map.texels)().swap(map.texels);
  baked.simplify = simplify_curves(curves, f);
  release_free_memory();  // the walk's lists (peak memory: each phase's freed blocks returned before the next's)
  {                       // the network is freed before the smoothing's buffers are made
    const std::vector<CurveSegment> network = network_segments(f);
    release_free_memory();  // its per-row lists
    baked.network_segments = network.size();
    if (network.empty())
      throw Error(ExitCode::invalid_input,
                  "no curve crosses a cell of the sample lattice (curves shorter than a texel between two texel "
                  "centres leave no discontinuity): nothing to bake");
    baked.distance = compute_distance_maps(network, options.band, f, progress);
  }
  release_free_memory();
  baked.max_smoothing_turn = smooth_gradient(f, options.smooth_iterations);
  return baked;
}

AssetWriter crease_asset_writer(BakedCrease&& baked, const CreaseBakeOptions& options, const InputRecord& map,
                                const CurvesRecord& curves) {
  CreaseField& f = baked.field;
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({map.to_json(), curves.to_json()});
  metadata["parameters"] = {{"width", f.width},
                            {"height", f.height},
                            {"smooth_iterations", options.smooth_iterations},
                            {"band", options.band}};
  metadata["conventions"] = normal_map_conventions();
  metadata["conventions"]["curves"] =
      "texel coordinates, x right, y = row down, the map spanning [0, W] x [0, H]; texel (x, row) centred at "
      "(x + 0.5, row + 0.5)";
  metadata["conventions"]["lattice"] =
      "sample (i, j) at (i - 0.5, j - 0.5), 0 <= i <= W + 1, 0 <= j <= H + 1, its normal the texel (i - 1, j - 1) "
      "clamped to the map; cell (i, j) spans [i - 0.5, i + 0.5] x [j - 0.5, j + 0.5]";
  metadata["conventions"]["signature"] =
      "crossing_h/crossing_v: t in [1/1024, 1 - 1/1024] along +x/+y from the edge's first sample, or -1; segments: "
      "bit m (0..3) joins edge points P_m and P_{m+1 mod 4} (edges top, right, bottom, left), bit 4 P0-P2, bit 5 "
      "P1-P3, bit 8 + b reverses segment b; a word of bit 6 alone is a junction cell, its point and spokes in "
      "junction_cells/junction_points/junction_spokes";
  metadata["conventions"]["gradient"] = "unit gradient of the distance, pointing away from the nearest point";
  metadata["conventions"]["side"] = "+1 right of the nearest directed segment as seen on screen (y down), else -1";
  metadata["statistics"] = {{"simplify", baked.simplify.to_json()},
                            {"network_segments", baked.network_segments},
                            {"distance", baked.distance.to_json()},
                            {"max_smoothing_turn_degrees", baked.max_smoothing_turn * 180.0 / M_PI}};
  AssetWriter writer("crease", std::move(metadata));
  add_crease_sections(writer, std::move(f));
  return writer;
}

}  // namespace mbk
