// The container rules formats/SPEC.md fixed after an independent reader had to guess them (where a file ends,
// where an empty section may lie, what JSON the metadata may be): the valid side of each rule. The invalid side
// is in corrupt_fixtures_test.cpp (findings 1007, 2009, 2015, 3009); tests/spec_reader checks both against a
// reader written from the spec alone.
#include <gtest/gtest.h>

#include <algorithm>

#include "formats/asset.h"
#include "formats/validate.h"
#include "tests/formats/asset_fixtures.h"

namespace mbk {
namespace {

using Bytes = std::vector<uint8_t>;

std::vector<int> error_ids(const Bytes& f) {
  std::vector<int> ids;
  for (const Finding& finding : validate_asset(f))
    if (finding.severity == Severity::error) ids.push_back(finding.id);
  return ids;
}

Bytes mip_with_empty_section() {
  AssetWriter w = test::mip_writer(5, 3);
  w.add<float>("empty", {0}, std::vector<float>{});
  return w.serialize();
}

TEST(ContainerRules, EmptyLastSectionEndsTheFileAtItsAlignedOffset) {
  const Bytes f = mip_with_empty_section();
  const uint64_t empty_offset = test::section_data_offset(f, 3);
  EXPECT_EQ(empty_offset % kSectionAlignment, 0u);
  EXPECT_EQ(empty_offset, f.size());  // the padding after level_2 belongs to the file, and nothing after it
  EXPECT_TRUE(error_ids(f).empty());
}

TEST(ContainerRules, EmptySectionMayLieAtAnotherSectionsStartOrEnd) {
  for (size_t other : {0, 1}) {
    Bytes f = mip_with_empty_section();
    store_le<uint64_t>(&f[test::entry_offset(f, 3) + entry_field::offset], test::section_data_offset(f, other));
    // The file now ends with level_2's data: the padding that led to the empty section's old offset goes.
    f.resize(test::section_data_offset(f, 2) +
             load_le<uint64_t>(&f[test::entry_offset(f, 2) + entry_field::byte_length]));
    store_le<uint64_t>(&f[header_field::file_size], f.size());
    test::reseal_header(f);
    EXPECT_TRUE(error_ids(f).empty()) << "at the start of section " << other;
  }
}

TEST(ContainerRules, EmptySectionInsideALaterEntrysSectionIsFound) {
  // The empty section's entry first in the table, before the section it lies inside: the overlap check must
  // not depend on the order of the entries.
  Bytes f = mip_with_empty_section();
  std::swap_ranges(f.begin() + test::entry_offset(f, 0), f.begin() + test::entry_offset(f, 1),
                   f.begin() + test::entry_offset(f, 3));
  store_le<uint64_t>(&f[test::entry_offset(f, 0) + entry_field::offset], test::section_data_offset(f, 3) + 64);
  test::reseal_header(f);
  EXPECT_EQ(error_ids(f), std::vector<int>{msg::sections_overlap.id});
}

TEST(ContainerRules, MetadataWhitespaceIsJson) {
  Bytes f = test::valid_mip_bytes();
  const uint64_t offset = load_le<uint64_t>(&f[header_field::metadata_offset]);
  std::string text(f.begin() + offset, f.begin() + offset + load_le<uint64_t>(&f[header_field::metadata_size]));
  auto m = nlohmann::json::parse(text);
  m["conventions"] = nlohmann::json::object();
  test::replace_metadata(f, "\n " + m.dump() + "\t");  // padded with spaces to the old size
  EXPECT_TRUE(error_ids(f).empty());
}

}  // namespace
}  // namespace mbk
