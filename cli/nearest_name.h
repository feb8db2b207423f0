// The name a mistyped command or option most likely meant ("mipp" -> "mip", "--thread" -> "--threads"), for
// "did you mean" hints: the closest by edit distance (Levenshtein), when it is close enough to be a typo, or the only
// name the typed text begins.
#pragma once

#include <string>
#include <vector>

namespace mbk::cli {

// "" when no name is close.
std::string nearest_name(const std::string& typed, const std::vector<std::string>& names);

}  // namespace mbk::cli
