// Baking asset kind `crease` (formats/SPEC.md "Kind 6: crease"; formats/crease_field.h): [Parilov05]'s
// preprocessing for normal maps with discontinuities. Sec. 4.1 simplification (crease_network.h), Sec. 4.2
// distance and gradient maps (crease_distance.h) and constrained gradient smoothing (gradient_smoothing.h),
// stored with the normal map itself so that the reconstruction (formats/crease_reconstruction.h) needs only
// the asset.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "formats/asset_writer.h"
#include "formats/crease_field.h"
#include "libbake/core/progress.h"
#include "libbake/crease/crease_distance.h"
#include "libbake/crease/crease_network.h"
#include "libbake/crease/curve_set.h"
#include "libbake/image/normal_map.h"

namespace mbk {

inline constexpr uint32_t kCreaseDefaultSmoothIterations = 10;
inline constexpr uint32_t kCreaseMaxSmoothIterations = 10000;
inline constexpr double kCreaseDefaultBand = 4.0;

struct CreaseBakeOptions {
  uint32_t smooth_iterations = kCreaseDefaultSmoothIterations;
  double band = kCreaseDefaultBand;  // texels; the distance is exact where it is <= band
};

struct BakedCrease {
  CreaseField field;
  SimplifyStatistics simplify;
  DistanceStatistics distance;
  uint64_t network_segments = 0;
  double max_smoothing_turn = 0.0;  // radians
};

// Throws Error(bad_command_line) for a band not in (0, 1e6] or too many iterations; Error(invalid_input) when
// no curve crosses a cell edge (nothing to bake). The map's texels are freed once copied into the field (pass a
// copy to keep them): the bake's peak memory is then about the field's.
BakedCrease bake_crease(NormalMap map, const CurveSet& curves, const CreaseBakeOptions& options, Progress& progress);

// What the asset records about the curves file.
struct CurvesRecord {
  std::string path, content_hash;
  uint64_t bytes = 0, curves = 0, segments = 0;
  nlohmann::json to_json() const;
};
// The record of a curves file as read (its bytes hashed again from disk). Error(io_failure) when unreadable.
CurvesRecord curves_record(const std::filesystem::path& path, const CurveSet& curves);

// The field's arrays move into the writer (the file's bytes are then in memory once); baked keeps its statistics.
AssetWriter crease_asset_writer(BakedCrease&& baked, const CreaseBakeOptions& options, const InputRecord& map,
                                const CurvesRecord& curves);

}  // namespace mbk
