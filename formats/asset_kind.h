// The registry of asset kinds. Each technique declares its kind here: a stable id (stored in the header),
// a name (stored in the metadata), the sections it requires, which other section names it knows, and the
// invariant checks `validate` runs. Adding a kind: a formats/kind_<name>.cpp defining its AssetKind, a line
// in asset_kinds() (asset_kind.cpp), its findings block in validation_messages.h, and its page in SPEC.md.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "formats/element_type.h"
#include "formats/validation_messages.h"

namespace mbk {

class Asset;

struct SectionRule {
  std::string name;
  std::vector<ElementType> types;  // accepted element types
  size_t rank;
};

struct AssetKind {
  uint32_t id;
  std::string_view name;
  std::string_view summary;
  std::vector<SectionRule> required_sections;
  // Whether a section name belongs to this kind (required or optional). Unknown ones get a warning.
  std::function<bool(const std::string&)> knows_section;
  // Appends findings about the kind's invariants. Called only on structurally sound assets whose
  // required sections exist with the right types and whose checksums match, by `validate` and by every reader
  // (Asset::open/parse), so they must stay cheap next to reading the file.
  std::function<void(const Asset&, std::vector<Finding>&)> check_invariants;
};

std::span<const AssetKind> asset_kinds();
const AssetKind* find_kind(uint32_t id);
const AssetKind* find_kind(std::string_view name);
// For a kind id that once existed and was retired: what it was and what to do (" (...)"); "" otherwise.
std::string_view retired_kind_note(uint32_t id);

// The declarations of each kind, one file each.
AssetKind mip_kind();
AssetKind lut_kind();
AssetKind rmq_kind();
AssetKind sh_kind();
AssetKind vmf_kind();
AssetKind colormap_kind();
AssetKind moments_kind();
AssetKind crease_kind();
AssetKind graph_kind();
AssetKind histogram_kind();
AssetKind neural_histogram_kind();

}  // namespace mbk
