// Helpers of the .mbk layout: section names, element counts and the XXH3-64 checksum (formats/SPEC.md).
#include "formats/container_layout.h"

#include <xxhash.h>

namespace mbk {

uint64_t SectionInfo::element_count() const {
  uint64_t n = 1;
  for (uint64_t d : shape) n *= d;
  return n;
}

bool is_valid_section_name(const std::string& name) {
  if (name.empty() || name.size() >= kSectionNameBytes) return false;
  if (!(name[0] >= 'a' && name[0] <= 'z')) return false;
  for (char c : name) {
    bool ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
    if (!ok) return false;
  }
  return true;
}

uint64_t checksum_of(const void* data, size_t size) { return XXH3_64bits(data, size); }

}  // namespace mbk
