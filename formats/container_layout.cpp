// Helpers of the .mbk layout: section names, element counts and the XXH3-64 checksums (formats/SPEC.md).
#include "formats/container_layout.h"

#include <xxhash.h>

#include <cstdio>
#include <new>

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

std::string checksum_hex(uint64_t checksum) {
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(checksum));
  return digits;
}

uint64_t header_checksum(const uint8_t* file, uint64_t metadata_offset, uint64_t metadata_size,
                         uint64_t section_table_offset, uint64_t section_table_size) {
  XXH3_state_t* state = XXH3_createState();
  if (!state) throw std::bad_alloc();
  XXH3_64bits_reset(state);
  XXH3_64bits_update(state, file, kChecksummedHeaderBytes);
  XXH3_64bits_update(state, file + metadata_offset, metadata_size);
  XXH3_64bits_update(state, file + section_table_offset, section_table_size);
  const uint64_t digest = XXH3_64bits_digest(state);
  XXH3_freeState(state);
  return digest;
}

}  // namespace mbk
