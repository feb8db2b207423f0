// Deterministic mutation testing of the reader: every truncation, many extensions and thousands of bit
// flips of valid files (over 10,000 mutants in all) must each end in a clean refusal (an mbk::Error with
// exit code 3 or 5, and an error finding from validate) — never a crash, never a corrupt file accepted.
// Every byte of a file is covered by a checksum or must be zero padding, so no mutant may pass.
#include <gtest/gtest.h>

#include <random>

#include "formats/asset.h"
#include "formats/validate.h"
#include "tests/formats/asset_fixtures.h"

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

struct MutationCounts {
  int truncations = 0, extensions = 0, flips = 0;
  int total() const { return truncations + extensions + flips; }
};

MutationCounts mutate_all(const Bytes& valid, uint32_t seed, int flips) {
  MutationCounts counts;
  for (size_t len = 0; len < valid.size(); ++len, ++counts.truncations)
    EXPECT_TRUE(refused(Bytes(valid.begin(), valid.begin() + len), "truncated to " + std::to_string(len)));
  std::mt19937 rng(seed);  // fixed seed and algorithm: the same mutants on every machine
  for (int extra = 1; extra <= 256; ++extra, ++counts.extensions) {
    Bytes m = valid;
    for (int i = 0; i < extra; ++i) m.push_back(extra % 2 ? 0 : uint8_t(rng()));
    EXPECT_TRUE(refused(m, "extended by " + std::to_string(extra)));
  }
  for (int i = 0; i < flips; ++i, ++counts.flips) {
    Bytes m = valid;
    const size_t byte = rng() % m.size();
    const int bits = 1 + int(rng() % 3);  // single, double and triple bit flips in one byte
    for (int b = 0; b < bits; ++b) m[byte] ^= uint8_t(1u << (rng() % 8));
    if (m == valid) continue;  // flips that cancel out leave the file valid
    EXPECT_TRUE(refused(m, "bits flipped at byte " + std::to_string(byte)));
  }
  return counts;
}

TEST(ReaderMutation, TenThousandMutantsAllRefusedCleanly) {
  MutationCounts small = mutate_all(test::valid_mip_bytes(5, 3), 12345, 3000);
  MutationCounts large = mutate_all(test::valid_mip_bytes(24, 13), 777, 3000);
  EXPECT_GE(small.total() + large.total(), 10000);
}

TEST(ReaderMutation, EveryBitOfTheHeaderMatters) {
  const Bytes valid = test::valid_mip_bytes(3, 2);
  for (size_t byte = 0; byte < kHeaderSize; ++byte)
    for (int bit = 0; bit < 8; ++bit) {
      Bytes m = valid;
      m[byte] ^= uint8_t(1u << bit);
      EXPECT_TRUE(refused(m, "header byte " + std::to_string(byte) + " bit " + std::to_string(bit)));
    }
}

}  // namespace
}  // namespace mbk
