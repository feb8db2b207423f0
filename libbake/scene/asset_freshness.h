// Whether an asset file on disk is what the plan would bake now. `bake` skips up-to-date files and
// rebuilds the others; `render` refuses stale ones. A file is up to date when it opens as a valid asset
// (formats/asset.h: structure, checksums, required sections) of the planned kind, records exactly one
// input whose content hash, convention and invalid-texel policy match the scene's normal map now, and
// records the recipe's canonical parameters with the same values.
#pragma once

#include <filesystem>
#include <string>

#include "libbake/scene/bake_plan.h"

namespace mbk {

enum class AssetState { missing, stale, up_to_date };

struct AssetFreshness {
  AssetState state = AssetState::missing;
  std::string reason;  // one line: "no file yet", "input changed (...)", "up to date (...)"
};

// `input_hash` is file_content_hash() of the planned input, computed by the caller (once).
AssetFreshness check_asset_freshness(const PlannedAsset& planned, const std::filesystem::path& file,
                                     const std::string& input_hash);

}  // namespace mbk
