// Helpers of the .mbk layout: section names, element counts and the XXH3-64 checksums (formats/SPEC.md).
#include "formats/container_layout.h"

#include <xxhash.h>

#include <algorithm>
#include <cstdio>
#include <new>

#include "formats/byte_io.h"

namespace mbk {

uint64_t SectionInfo::element_count() const {
  uint64_t n = 1;
  for (uint64_t d : shape) n *= d;
  return n;
}

ContainerHeader load_header(const uint8_t* b) {
  ContainerHeader h;
  h.major = load_le<uint16_t>(b + header_field::major);
  h.minor = load_le<uint16_t>(b + header_field::minor);
  h.kind = load_le<uint32_t>(b + header_field::kind);
  h.file_size = load_le<uint64_t>(b + header_field::file_size);
  h.metadata_offset = load_le<uint64_t>(b + header_field::metadata_offset);
  h.metadata_size = load_le<uint64_t>(b + header_field::metadata_size);
  h.section_table_offset = load_le<uint64_t>(b + header_field::section_table_offset);
  h.section_count = load_le<uint32_t>(b + header_field::section_count);
  h.section_entry_size = load_le<uint32_t>(b + header_field::section_entry_size);
  h.checksum = load_le<uint64_t>(b + header_field::checksum);
  return h;
}

void store_header(uint8_t* b, const ContainerHeader& h) {
  std::copy(kMagic.begin(), kMagic.end(), b + header_field::magic);
  store_le<uint16_t>(b + header_field::major, h.major);
  store_le<uint16_t>(b + header_field::minor, h.minor);
  store_le<uint32_t>(b + header_field::kind, h.kind);
  store_le<uint64_t>(b + header_field::file_size, h.file_size);
  store_le<uint64_t>(b + header_field::metadata_offset, h.metadata_offset);
  store_le<uint64_t>(b + header_field::metadata_size, h.metadata_size);
  store_le<uint64_t>(b + header_field::section_table_offset, h.section_table_offset);
  store_le<uint32_t>(b + header_field::section_count, h.section_count);
  store_le<uint32_t>(b + header_field::section_entry_size, h.section_entry_size);
  store_le<uint64_t>(b + header_field::checksum, h.checksum);
}

void store_section_entry(uint8_t* e, const SectionInfo& s) {
  std::copy(s.name.begin(), s.name.end(), e + entry_field::name);
  store_le<uint32_t>(e + entry_field::element_type, static_cast<uint32_t>(s.type));
  store_le<uint32_t>(e + entry_field::rank, static_cast<uint32_t>(s.shape.size()));
  for (size_t d = 0; d < s.shape.size(); ++d) store_le<uint64_t>(e + entry_field::shape + 8 * d, s.shape[d]);
  store_le<uint64_t>(e + entry_field::offset, s.offset);
  store_le<uint64_t>(e + entry_field::byte_length, s.byte_length);
  store_le<uint64_t>(e + entry_field::checksum, s.checksum);
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

StreamedChecksum::StreamedChecksum() : state_(XXH3_createState()) {
  if (!state_) throw std::bad_alloc();
  XXH3_64bits_reset(static_cast<XXH3_state_t*>(state_));
}

StreamedChecksum::~StreamedChecksum() { XXH3_freeState(static_cast<XXH3_state_t*>(state_)); }

void StreamedChecksum::update(const void* data, size_t size) {
  XXH3_64bits_update(static_cast<XXH3_state_t*>(state_), data, size);
}

uint64_t StreamedChecksum::digest() const { return XXH3_64bits_digest(static_cast<const XXH3_state_t*>(state_)); }

uint64_t header_checksum(const uint8_t* file, uint64_t metadata_offset, uint64_t metadata_size,
                         uint64_t section_table_offset, uint64_t section_table_size) {
  StreamedChecksum checksum;
  checksum.update(file, kChecksummedHeaderBytes);
  checksum.update(file + metadata_offset, metadata_size);
  checksum.update(file + section_table_offset, section_table_size);
  return checksum.digest();
}

}  // namespace mbk
