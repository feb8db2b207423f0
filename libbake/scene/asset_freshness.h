// Whether an asset file on disk is what the plan would bake now. `bake` skips up-to-date files and
// rebuilds the others; `render` refuses stale ones. A file is up to date when it opens as a valid asset
// (formats/asset.h: structure, checksums, required sections) of the planned kind and of this microbake
// version, records as many inputs as the recipe has, each with the content hash of the recipe's input file
// now (and, for normal maps, the same requested convention and invalid-texel policy), and records the recipe's
// canonical parameters with the same values. An input file that no longer exists is not compared (assets
// can ship without their sources; `bake` refuses missing inputs before it gets here).
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

AssetFreshness check_asset_freshness(const PlannedAsset& planned, const std::filesystem::path& file);

}  // namespace mbk
