// The fixed byte layout of the .mbk container, version 1.0 (formats/SPEC.md is the normative description;
// this header mirrors it field by field). All integers are little-endian.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "formats/element_type.h"

namespace mbk {

// "\x89MBK\r\n\x1a\n": the high byte catches 7-bit channels, CR LF and LF catch text-mode line-ending
// conversion in either direction, and 0x1A stops `type` on DOS (the PNG signature's reasoning).
inline constexpr std::array<uint8_t, 8> kMagic = {0x89, 'M', 'B', 'K', '\r', '\n', 0x1A, '\n'};

inline constexpr uint16_t kFormatMajor = 1;
inline constexpr uint16_t kFormatMinor = 0;

inline constexpr uint64_t kHeaderSize = 64;              // bytes 0..63
inline constexpr uint64_t kChecksummedHeaderBytes = 56;  // the header checksum covers bytes 0..55
inline constexpr uint32_t kSectionEntrySize = 128;       // v1.0 entries; readers accept larger (later minors)
inline constexpr uint64_t kSectionAlignment = 64;        // every section's data starts at a multiple of this
inline constexpr size_t kSectionNameBytes = 32;          // NUL-padded, 1..31 characters
inline constexpr size_t kMaxRank = 6;
inline constexpr uint32_t kMaxSections = 65536;

// Where each header field lies: byte offsets in the 64-byte header (SPEC section 2).
namespace header_field {
inline constexpr size_t magic = 0;                  // u8[8]
inline constexpr size_t major = 8;                  // u16
inline constexpr size_t minor = 10;                 // u16
inline constexpr size_t kind = 12;                  // u32
inline constexpr size_t file_size = 16;             // u64
inline constexpr size_t metadata_offset = 24;       // u64
inline constexpr size_t metadata_size = 32;         // u64
inline constexpr size_t section_table_offset = 40;  // u64
inline constexpr size_t section_count = 48;         // u32
inline constexpr size_t section_entry_size = 52;    // u32
inline constexpr size_t checksum = 56;              // u64, over bytes 0..55, the metadata and the section table
}  // namespace header_field

// Where each field of a section-table entry lies: byte offsets from the entry's first byte (SPEC section 4).
namespace entry_field {
inline constexpr size_t name = 0;           // char[32], NUL-padded
inline constexpr size_t element_type = 32;  // u32
inline constexpr size_t rank = 36;          // u32
inline constexpr size_t shape = 40;         // u64[6], outermost first; entries at index >= rank are 0
inline constexpr size_t offset = 88;        // u64
inline constexpr size_t byte_length = 96;   // u64
inline constexpr size_t checksum = 104;     // u64
inline constexpr size_t reserved = 112;     // u8[16], zero, up to kSectionEntrySize
}  // namespace entry_field

static_assert(header_field::checksum == kChecksummedHeaderBytes && header_field::checksum + 8 == kHeaderSize);
static_assert(entry_field::shape + 8 * kMaxRank == entry_field::offset &&
              entry_field::name + kSectionNameBytes == entry_field::element_type);
static_assert(entry_field::reserved + 16 == kSectionEntrySize);

struct ContainerHeader {
  uint16_t major = kFormatMajor;
  uint16_t minor = kFormatMinor;
  uint32_t kind = 0;
  uint64_t file_size = 0;
  uint64_t metadata_offset = 0;
  uint64_t metadata_size = 0;
  uint64_t section_table_offset = 0;
  uint32_t section_count = 0;
  uint32_t section_entry_size = kSectionEntrySize;
  uint64_t checksum = 0;  // XXH3-64 of header bytes 0..55, then the metadata, then the section table
};

// The header's fields from its 64 bytes, and back (the magic is written, not read: callers check it first).
ContainerHeader load_header(const uint8_t* header);
void store_header(uint8_t* header, const ContainerHeader& h);

struct SectionInfo {
  std::string name;
  ElementType type = ElementType::u8;
  std::vector<uint64_t> shape;  // rank 1..6, outermost dimension first (row-major)
  uint64_t offset = 0;          // absolute, 64-byte aligned
  uint64_t byte_length = 0;     // product(shape) * element size
  uint64_t checksum = 0;        // XXH3-64 (seed 0) of the section's bytes

  uint64_t element_count() const;  // product of shape; only call on a validated section
};

// Writes a v1.0 section-table entry (kSectionEntrySize bytes, which the caller has zeroed) for `s`.
void store_section_entry(uint8_t* entry, const SectionInfo& s);

// Section names: 1..31 characters from [a-z0-9_.-], starting with a letter.
bool is_valid_section_name(const std::string& name);

// 64-bit XXH3 (seed 0), the one checksum of the format.
uint64_t checksum_of(const void* data, size_t size);

// The same checksum over bytes given in consecutive pieces (a section written while it is produced): digest()
// equals checksum_of() of the pieces joined.
class StreamedChecksum {
 public:
  StreamedChecksum();
  ~StreamedChecksum();
  StreamedChecksum(const StreamedChecksum&) = delete;
  StreamedChecksum& operator=(const StreamedChecksum&) = delete;
  void update(const void* data, size_t size);
  uint64_t digest() const;

 private:
  void* state_;  // XXH3_state_t (xxhash.h stays out of this header)
};

// A checksum as microbake prints it: 16 lowercase hex digits, most significant first (`info`, the "xxh3:..."
// content hashes of metadata inputs, the names `bake` gives assets).
std::string checksum_hex(uint64_t checksum);

// The header checksum (header bytes 56..63): XXH3-64 of header bytes 0..55, then the metadata block, then the
// section table, hashed as one stream. The caller has checked that both regions lie inside `file`.
uint64_t header_checksum(const uint8_t* file, uint64_t metadata_offset, uint64_t metadata_size,
                         uint64_t section_table_offset, uint64_t section_table_size);

}  // namespace mbk
