// Runs every check on an asset's bytes and collects findings (see validate.h).
#include "formats/validate.h"

#include "formats/asset.h"

namespace mbk {

std::vector<Finding> validate_asset(std::span<const uint8_t> bytes) {
  std::vector<Finding> findings;
  auto parsed = parse_container(bytes, findings);
  if (!parsed) return findings;
  check_sections(*parsed, bytes, findings);
  if (has_errors(findings)) return findings;
  const Asset asset = Asset::parse_structure(std::vector<uint8_t>(bytes.begin(), bytes.end()), "");
  check_kind_invariants(asset, findings);
  return findings;
}

void check_kind_invariants(const Asset& asset, std::vector<Finding>& findings) {
  if (!asset.kind().check_invariants) return;
  try {
    asset.kind().check_invariants(asset, findings);
  } catch (const nlohmann::json::exception& e) {  // a checker read a metadata value whose type it did not test
    findings.push_back(make_finding(msg::metadata_wrong_type, e.what()));
  }
}

bool has_errors(const std::vector<Finding>& findings, bool warnings_as_errors) {
  return first_error(findings, warnings_as_errors) != nullptr;
}

const Finding* first_error(const std::vector<Finding>& findings, bool warnings_as_errors) {
  for (const Finding& f : findings)
    if (f.severity == Severity::error || warnings_as_errors) return &f;
  return nullptr;
}

ExitCode exit_code_for(const Finding& f) {
  return f.id == msg::newer_major.id ? ExitCode::unsupported : ExitCode::invalid_input;
}

void throw_first_error(const std::vector<Finding>& findings, const std::string& where) {
  if (const Finding* f = first_error(findings))
    throw Error(exit_code_for(*f), "invalid asset: [" + std::to_string(f->id) + "] " + f->message, where);
}

}  // namespace mbk
