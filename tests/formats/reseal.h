// Resealing .mbk bytes after a change: recomputing the checksums around it, so that the checks behind the
// checksums see the change. Shared by the corrupt fixtures (asset_fixtures.h), the mutation test and the fuzz
// target (tests/fuzz/fuzz_asset.cpp); never trusts the header it reads more than the reader does.
#pragma once

#include <cstdint>
#include <vector>

#include "formats/byte_io.h"
#include "formats/container_layout.h"

namespace mbk::test {

// The regions the header of `f` (at least kHeaderSize bytes) names, as recorded, unchecked.
struct RecordedRegions {
  uint64_t metadata_offset, metadata_size, table_offset, entry_count, entry_size;
  uint64_t table_size() const { return entry_count * entry_size; }  // both < 2^32: no overflow
};
inline RecordedRegions recorded_regions(const std::vector<uint8_t>& f) {
  return {load_le<uint64_t>(&f[header_field::metadata_offset]), load_le<uint64_t>(&f[header_field::metadata_size]),
          load_le<uint64_t>(&f[header_field::section_table_offset]), load_le<uint32_t>(&f[header_field::section_count]),
          load_le<uint32_t>(&f[header_field::section_entry_size])};
}

// Recomputes the header checksum of `f`, whose metadata and section table must lie inside it.
inline void reseal_header(std::vector<uint8_t>& f) {
  const RecordedRegions r = recorded_regions(f);
  store_le<uint64_t>(&f[header_field::checksum],
                     header_checksum(f.data(), r.metadata_offset, r.metadata_size, r.table_offset, r.table_size()));
}

// `f` with every section checksum and then the header checksum recomputed, wherever its own header says the
// regions are; anything that would need a read outside `f` is left as it is.
inline std::vector<uint8_t> resealed(std::vector<uint8_t> f) {
  const uint64_t n = f.size();
  if (n < kHeaderSize) return f;
  const RecordedRegions r = recorded_regions(f);
  if (r.metadata_offset > n || r.metadata_size > n - r.metadata_offset || r.table_offset > n ||
      r.table_size() > n - r.table_offset)
    return f;
  if (r.entry_size >= kSectionEntrySize)
    for (uint64_t i = 0; i < r.entry_count; ++i) {
      uint8_t* e = &f[r.table_offset + i * r.entry_size];
      const uint64_t off = load_le<uint64_t>(e + entry_field::offset),
                     len = load_le<uint64_t>(e + entry_field::byte_length);
      if (off <= n && len <= n - off) store_le<uint64_t>(e + entry_field::checksum, checksum_of(f.data() + off, len));
    }
  reseal_header(f);
  return f;
}

}  // namespace mbk::test
