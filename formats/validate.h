// `microbake validate` in library form: structure, checksums, required sections, then the kind's
// invariants (only on assets that are structurally sound). Findings come from validation_messages.h.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "formats/error.h"
#include "formats/validation_messages.h"

namespace mbk {

class Asset;

std::vector<Finding> validate_asset(std::span<const uint8_t> bytes);
// Appends the findings of the kind's invariants on an asset whose structure and checksums are sound (validate and
// every reader run them). A metadata value of a JSON type the checks did not expect is a finding (2014), never an
// exception.
void check_kind_invariants(const Asset& asset, std::vector<Finding>& findings);

bool has_errors(const std::vector<Finding>& findings, bool warnings_as_errors = false);

// The first finding that makes an asset invalid (an error, or any finding under `warnings_as_errors`), or null.
const Finding* first_error(const std::vector<Finding>& findings, bool warnings_as_errors = false);
// The exit code of refusing an asset for `f`: unsupported (5) for a newer major version, else invalid_input (3).
ExitCode exit_code_for(const Finding& f);
// Throws Error(exit_code_for(f), "invalid asset: [id] message", where) for the first error finding, if any.
void throw_first_error(const std::vector<Finding>& findings, const std::string& where);

}  // namespace mbk
