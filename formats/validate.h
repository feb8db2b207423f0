// `microbake validate` in library form: structure, checksums, required sections, then the kind's
// invariants (only on assets that are structurally sound). Findings come from validation_messages.h.
#pragma once

#include <span>
#include <vector>

#include "formats/validation_messages.h"

namespace mbk {

std::vector<Finding> validate_asset(std::span<const uint8_t> bytes);
bool has_errors(const std::vector<Finding>& findings, bool warnings_as_errors = false);

}  // namespace mbk
