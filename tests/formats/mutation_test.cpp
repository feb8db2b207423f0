// Deterministic mutation testing of the reader: every truncation, many extensions and thousands of bit
// flips of valid files (over 10,000 mutants in all) must each end in a clean refusal (an mbk::Error with
// exit code 3 or 5, and an error finding from validate) — never a crash, never a corrupt file accepted.
// Every byte of a file is covered by a checksum or must be zero padding, so no mutant may pass.
// Each mutant is tried a second time resealed (its checksums recomputed, tests/formats/reseal.h), so that the
// checks behind the checksums see it too: it must then be refused cleanly the same way, or, when the change is
// one the format allows (a metadata value, a data byte), be accepted with every section inside the file and
// readable, and validate must end in findings, not a crash.
#include <gtest/gtest.h>

#include <random>

#include "formats/asset.h"
#include "formats/validate.h"
#include "tests/formats/asset_fixtures.h"
#include "tests/formats/reseal.h"

namespace mbk {
namespace {

using Bytes = std::vector<uint8_t>;

// Returns true when the mutant is refused cleanly by both the reader and the validator.
::testing::AssertionResult refused(const Bytes& mutant, const std::string& what) {
  try {
    Asset::parse(mutant, "mutant");
    return ::testing::AssertionFailure() << what << ": reader accepted a corrupted file";
  } catch (const Error& e) {
    if (e.code() != ExitCode::invalid_input && e.code() != ExitCode::unsupported)
      return ::testing::AssertionFailure() << what << ": unexpected exit code " << int(e.code());
  }
  if (!has_errors(validate_asset(mutant))) return ::testing::AssertionFailure() << what << ": validate found no error";
  return ::testing::AssertionSuccess();
}

// What became of the resealed mutants: accepted, or refused by a check behind the checksums although the
// mutant as it was had been refused by a checksum (resealing let it reach deeper).
struct ResealedCounts {
  int accepted = 0, refused_deeper = 0;
};

bool is_checksum_finding(int id) {
  return id == msg::header_checksum_mismatch.id || id == msg::section_checksum_mismatch.id;
}

// A resealed mutant must be refused cleanly, or accepted with every section inside the file and readable.
::testing::AssertionResult refused_or_sound(const Bytes& mutant, const std::string& what, ResealedCounts& counts) {
  const Bytes sealed = test::resealed(mutant);
  const std::vector<Finding> findings = validate_asset(sealed);  // must return, whatever the bytes
  const std::vector<Finding> unsealed = validate_asset(mutant);
  const Finding* unsealed_first = first_error(unsealed);
  const bool unsealed_by_checksum = unsealed_first && is_checksum_finding(unsealed_first->id);
  try {
    const Asset a = Asset::parse(sealed, "resealed mutant");
    for (const SectionInfo& s : a.sections()) {
      uint64_t end = 0;
      if (__builtin_add_overflow(s.offset, s.byte_length, &end) || end > sealed.size())
        return ::testing::AssertionFailure() << what << " (resealed): section '" << s.name << "' out of bounds";
      const std::span<const uint8_t> data = a.bytes_of(s);
      if (data.size() != s.byte_length || checksum_of(data.data(), data.size()) != s.checksum)
        return ::testing::AssertionFailure() << what << " (resealed): section '" << s.name << "' not readable";
    }
    ++counts.accepted;
  } catch (const Error& e) {
    if (e.code() != ExitCode::invalid_input && e.code() != ExitCode::unsupported)
      return ::testing::AssertionFailure() << what << " (resealed): unexpected exit code " << int(e.code());
    const Finding* first = first_error(findings);
    if (!first) return ::testing::AssertionFailure() << what << " (resealed): reader refused, validate found no error";
    if (unsealed_by_checksum && !is_checksum_finding(first->id)) ++counts.refused_deeper;
  }
  return ::testing::AssertionSuccess();
}

struct MutationCounts {
  int truncations = 0, extensions = 0, flips = 0;
  ResealedCounts resealed;
  int total() const { return truncations + extensions + flips; }
};

MutationCounts mutate_all(const Bytes& valid, uint32_t seed, int flips) {
  MutationCounts counts;
  for (size_t len = 0; len < valid.size(); ++len, ++counts.truncations) {
    const Bytes m(valid.begin(), valid.begin() + len);
    EXPECT_TRUE(refused(m, "truncated to " + std::to_string(len)));
    EXPECT_TRUE(refused_or_sound(m, "truncated to " + std::to_string(len), counts.resealed));
  }
  std::mt19937 rng(seed);  // fixed seed and algorithm: the same mutants on every machine
  for (int extra = 1; extra <= 256; ++extra, ++counts.extensions) {
    Bytes m = valid;
    for (int i = 0; i < extra; ++i) m.push_back(extra % 2 ? 0 : uint8_t(rng()));
    EXPECT_TRUE(refused(m, "extended by " + std::to_string(extra)));
    EXPECT_TRUE(refused_or_sound(m, "extended by " + std::to_string(extra), counts.resealed));
  }
  for (int i = 0; i < flips; ++i, ++counts.flips) {
    Bytes m = valid;
    const size_t byte = rng() % m.size();
    const int bits = 1 + int(rng() % 3);  // single, double and triple bit flips in one byte
    for (int b = 0; b < bits; ++b) m[byte] ^= uint8_t(1u << (rng() % 8));
    if (m == valid) continue;  // flips that cancel out leave the file valid
    EXPECT_TRUE(refused(m, "bits flipped at byte " + std::to_string(byte)));
    EXPECT_TRUE(refused_or_sound(m, "bits flipped at byte " + std::to_string(byte), counts.resealed));
  }
  return counts;
}

TEST(ReaderMutation, TenThousandMutantsAllRefusedCleanly) {
  MutationCounts small = mutate_all(test::valid_mip_bytes(5, 3), 12345, 3000);
  MutationCounts large = mutate_all(test::valid_mip_bytes(24, 13), 777, 3000);
  EXPECT_GE(small.total() + large.total(), 10000);
  // Resealing must let mutants reach the checks behind the checksums, and some flips (in metadata values or
  // section data) are changes the container allows: both outcomes must occur, or the resealed pass tests nothing.
  const int deeper = small.resealed.refused_deeper + large.resealed.refused_deeper;
  const int accepted = small.resealed.accepted + large.resealed.accepted;
  EXPECT_GT(deeper, 1000) << "resealed mutants refused by a check behind the checksums";
  EXPECT_GT(accepted, 1000) << "resealed mutants accepted";
}

TEST(ReaderMutation, EveryBitOfTheHeaderMatters) {
  const Bytes valid = test::valid_mip_bytes(3, 2);
  ResealedCounts counts;
  for (size_t byte = 0; byte < kHeaderSize; ++byte)
    for (int bit = 0; bit < 8; ++bit) {
      Bytes m = valid;
      m[byte] ^= uint8_t(1u << bit);
      EXPECT_TRUE(refused(m, "header byte " + std::to_string(byte) + " bit " + std::to_string(bit)));
      EXPECT_TRUE(refused_or_sound(m, "header byte " + std::to_string(byte) + " bit " + std::to_string(bit), counts));
    }
}

}  // namespace
}  // namespace mbk
