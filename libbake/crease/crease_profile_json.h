// A crease profile ([Parilov05] Sec. 3, Eq. (1); formats/crease_reconstruction.h) from its JSON form, as a scene
// names it for the `crease` effect:
//   {"kind": "v" | "rounded" | "step" | "table", "depth": 1, "width": 2, "table": [h0, h1, ...],
//    "blend_start": 0, "blend_end": <width>}
// Every key is optional (defaults above; "table" is required for kind "table" and refused for the others).
// depth is the profile's height change over `width` texels (positive: a groove, negative: a ridge); b(d) rises
// from 0 at blend_start (w0) to 1 at blend_end (w). blend_end = 0 means the map everywhere (b = 1).
// Unknown keys and out-of-range values are Error(invalid_input) naming `where` + the key.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "formats/crease_reconstruction.h"

namespace mbk {

CreaseProfile crease_profile_from_json(const nlohmann::json& object, const std::string& where);
// Every key with its value (defaults filled in; "table" only for kind table): read back as the same profile.
nlohmann::json crease_profile_to_json(const CreaseProfile& profile);

}  // namespace mbk
