// libFuzzer target for the .mbk reader and validator (scripts/fuzz-reader.sh; README "Fuzzing").
// Any input must end in findings or an mbk::Error, never a crash or a hang. Each input is tried as it is
// and, so that the fuzzer can reach the checks behind the checksums, once more with its header and section
// checksums recomputed wherever the header's regions lie inside the input.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "formats/asset.h"
#include "formats/byte_io.h"
#include "formats/container_layout.h"
#include "formats/validate.h"

namespace {

void exercise(std::vector<uint8_t> bytes) {
  (void)mbk::validate_asset(bytes);
  try {
    mbk::Asset a = mbk::Asset::parse(std::move(bytes), "fuzz");
    for (const auto& s : a.sections()) (void)a.bytes_of(s);
  } catch (const mbk::Error&) {
  }
}

// Recomputes checksums where the input's own header says where the regions are; leaves anything that
// would need an out-of-bounds read alone.
std::vector<uint8_t> resealed(std::vector<uint8_t> f) {
  using mbk::load_le;
  const uint64_t n = f.size();
  if (n < mbk::kHeaderSize) return f;
  const uint64_t meta_off = load_le<uint64_t>(&f[24]), meta_size = load_le<uint64_t>(&f[32]);
  const uint64_t table_off = load_le<uint64_t>(&f[40]);
  const uint64_t count = load_le<uint32_t>(&f[48]), entry = load_le<uint32_t>(&f[52]);
  const uint64_t table_size = count * entry;
  if (meta_off > n || meta_size > n - meta_off || table_off > n || table_size > n - table_off) return f;
  if (entry >= mbk::kSectionEntrySize)
    for (uint64_t i = 0; i < count; ++i) {
      uint8_t* e = &f[table_off + i * entry];
      const uint64_t off = load_le<uint64_t>(e + 88), len = load_le<uint64_t>(e + 96);
      if (off <= n && len <= n - off) mbk::store_le<uint64_t>(e + 104, mbk::checksum_of(&f[off], len));
    }
  std::vector<uint8_t> covered(f.begin(), f.begin() + mbk::kChecksummedHeaderBytes);
  covered.insert(covered.end(), f.begin() + meta_off, f.begin() + meta_off + meta_size);
  covered.insert(covered.end(), f.begin() + table_off, f.begin() + table_off + table_size);
  mbk::store_le<uint64_t>(&f[56], mbk::checksum_of(covered.data(), covered.size()));
  return f;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<uint8_t> bytes(data, data + size);
  exercise(bytes);
  exercise(resealed(std::move(bytes)));
  return 0;
}
