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

// The file of a planned asset inside `folder`. With every input present, folder / file_name. With an input
// missing (assets shipped without their sources), the one file `<stem>.<kind>.<hash>.mbk` in the folder that is up
// to date with what can still be compared (its kind, version, parameters, conventions, repair policy and the hashes
// of the inputs still present); "" when none is. Error(invalid_input) when several are (an older bake of another
// map version not pruned: `bake --prune` removes it).
std::filesystem::path find_baked_asset(const PlannedAsset& planned, const std::filesystem::path& folder);

}  // namespace mbk
