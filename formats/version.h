// The version of microbake: what `--version` prints, what every asset records as its producer, and what `bake`
// compares to decide that an asset baked by another version must be rebaked. Defined in version.cpp alone (its
// value comes from CMakeLists.txt's project version), so that a version bump recompiles one file.
#pragma once

#include <string>

namespace mbk {

const std::string& microbake_version();

}  // namespace mbk
