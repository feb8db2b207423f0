// Reading .mbk files (formats/SPEC.md). parse_container() checks structure and reports findings without
// throwing; Asset::open()/parse() build on it, verify every checksum, the kind's required sections and its
// invariants (formats/validate.h), and throw the first error as mbk::Error: io_failure (2) for unreadable files,
// invalid_input (3) for corrupt ones, unsupported (5) for a newer major version. The reader never trusts an offset,
// size or shape product before bounds-checking it, and never crashes on any byte string (tests/formats fuzz it).
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/asset_kind.h"
#include "formats/container_layout.h"
#include "formats/error.h"
#include "formats/validation_messages.h"

namespace mbk {

struct ParsedContainer {
  ContainerHeader header;
  nlohmann::json metadata;
  std::vector<SectionInfo> sections;
};

// Structural checks: magic, versions, bounds, header checksum, metadata JSON, section entries.
// Returns the parsed container when no error was found (warnings may be present).
std::optional<ParsedContainer> parse_container(std::span<const uint8_t> bytes, std::vector<Finding>& findings);

// Checks each section's checksum, then the kind's required sections and types; appends findings.
void check_sections(const ParsedContainer& parsed, std::span<const uint8_t> bytes, std::vector<Finding>& findings);

class Asset {
 public:
  // Reads and checks a whole file, the kind's invariants included (those `validate` checks), so that no reader
  // (render, bake's freshness check, synth) uses an asset that `validate` rejects; `where` in errors is the path.
  static Asset open(const std::filesystem::path& path);
  // Checks bytes already in memory as open() does; `where` names them in errors.
  static Asset parse(std::vector<uint8_t> bytes, const std::string& where);
  // parse() without the kind's invariants: for `validate`, which reports those as findings itself.
  static Asset parse_structure(std::vector<uint8_t> bytes, const std::string& where);

  const ContainerHeader& header() const { return parsed_.header; }
  const nlohmann::json& metadata() const { return parsed_.metadata; }
  const std::vector<SectionInfo>& sections() const { return parsed_.sections; }
  const AssetKind& kind() const { return *kind_; }
  const std::string& where() const { return where_; }

  const SectionInfo* find(const std::string& name) const;
  // The section, or Error(invalid_input) naming it when absent.
  const SectionInfo& section(const std::string& name) const;
  std::span<const uint8_t> bytes_of(const SectionInfo& s) const;

  // A copy of a section's elements; Error(invalid_input) when its element type is not T.
  template <typename T>
  std::vector<T> read(const std::string& name) const {
    const SectionInfo& s = section(name);
    if (s.type != ElementOf<T>::value) throw type_error(s, ElementOf<T>::value);
    std::vector<T> out(s.element_count());
    auto b = bytes_of(s);
    std::memcpy(out.data(), b.data(), b.size());
    return out;
  }
  // A copy converted to float from f16, f32 or f64; Error(invalid_input) for integer sections.
  std::vector<float> read_as_float(const std::string& name) const;

 private:
  Asset() = default;
  Error type_error(const SectionInfo& s, ElementType wanted) const;
  std::vector<uint8_t> bytes_;
  ParsedContainer parsed_;
  const AssetKind* kind_ = nullptr;
  std::string where_;
};

}  // namespace mbk
