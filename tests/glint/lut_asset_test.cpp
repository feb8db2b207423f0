// The `lut` asset (libbake/glint/lut_asset.h): what the bake writes passes validate_asset() with no findings for
// generated kinds and odd sizes, reads back bit for bit through read_standardization_lut() (the evaluator's side),
// records inputs, parameters, conventions and statistics, and has the same bytes whatever the thread count.
#include <gtest/gtest.h>

#include <algorithm>

#include "formats/asset.h"
#include "formats/lut_layout.h"
#include "formats/validate.h"
#include "libbake/core/parallel.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/lut_asset.h"
#include "formats/standardization_lut.h"

namespace mbk {
namespace {

InputRecord record_of(const NormalMap& map) {
  InputRecord r;
  r.path = "in-memory.png";
  r.content_hash = "xxh3:0000000000000000";
  r.width = map.width, r.height = map.height, r.channels = 3;
  r.pixel_format = "uint16", r.convention = "+Y", r.invalid_policy = "error";
  return r;
}

std::vector<uint8_t> lut_bytes(const NormalMap& map, uint32_t size) {
  return lut_asset_writer(bake_standardization_lut(map, size, Progress::silent()), record_of(map)).serialize();
}

TEST(LutAsset, PassesValidationWithNoFindings) {
  for (const char* kind : {"bumps", "brushed", "scratches", "flakes", "leather", "panels"})
    for (const auto& [w, h, size] : {std::tuple{256u, 256u, kLutDefaultSize}, {37u, 1u, 128u}, {1u, 1u, 2u}}) {
      const std::vector<uint8_t> bytes = lut_bytes(generate_normal_map(kind, {w, h}, 5, Progress::silent()), size);
      const std::vector<Finding> findings = validate_asset(bytes);
      for (const Finding& f : findings)
        ADD_FAILURE() << kind << " " << w << "x" << h << ": " << f.id << " " << f.message;
    }
}

TEST(LutAsset, ReadsBackBitForBitWithItsMetadata) {
  const NormalMap map = generate_normal_map("flakes", {96, 64}, 2, Progress::silent());
  const BakedLut baked = bake_standardization_lut(map, 200, Progress::silent());
  const Asset asset = Asset::parse(lut_asset_writer(baked, record_of(map)).serialize(), "lut");
  const StandardizationLut read = read_standardization_lut(asset);
  ASSERT_EQ(read.size, 200u);
  for (int c = 0; c < 2; ++c) {
    const StandardizationChannelTables &a = baked.tables.channels[c], &b = read.channels[c];
    EXPECT_TRUE(std::ranges::equal(a.x(), b.x()));
    EXPECT_TRUE(std::ranges::equal(a.z(), b.z()));
  }
  const nlohmann::json& m = asset.metadata();
  EXPECT_EQ(m["kind"], "lut");
  EXPECT_EQ(m["parameters"], nlohmann::json({{"size", 200}}));
  EXPECT_EQ(m["inputs"][0], record_of(map).to_json());
  EXPECT_EQ(m["conventions"]["gaussian"], "standard normal N(0, 1)");
  EXPECT_EQ(m["conventions"]["normal_convention"], "+Y");
  for (int c = 0; c < 2; ++c) {
    const nlohmann::json& s = m["statistics"][std::string(kLutChannelNames[c])];
    EXPECT_EQ(s["round_trip_error"], baked.statistics[c].round_trip_error);
    EXPECT_EQ(s["forward_error"], baked.statistics[c].forward_error);
    EXPECT_EQ(s["inverse_error"], baked.statistics[c].inverse_error);
    EXPECT_EQ(s["knots"], baked.tables.channels[c].knots());
    EXPECT_EQ(s["clipped_tail_mass"], baked.statistics[c].clipped_tail_mass);
    EXPECT_EQ(s["min"], double(baked.tables.channels[c].x_lo()));
    EXPECT_EQ(s["distinct_values"], baked.statistics[c].distinct_values);
  }
}

TEST(LutAsset, ReaderRefusesOtherKindsAndBadShapes) {
  AssetWriter mip("mip", {{"inputs", nlohmann::json::array()},
                          {"parameters", {{"width", 1}, {"height", 1}, {"levels", 1}}},
                          {"conventions", nlohmann::json::object()},
                          {"statistics", nlohmann::json::object()}});
  mip.add<float>("level_0", {1, 1, 3}, std::vector<float>{0, 0, 1});
  EXPECT_THROW(read_standardization_lut(Asset::parse(mip.serialize(), "mip")), Error);
}

TEST(LutAsset, SameBytesWhateverTheThreads) {
  const NormalMap map = generate_normal_map("leather", {300, 200}, 9, Progress::silent());
  const int before = thread_count();
  set_thread_count(1);
  const std::vector<uint8_t> one = lut_bytes(map, kLutDefaultSize);
  set_thread_count(2);
  const std::vector<uint8_t> two = lut_bytes(map, kLutDefaultSize);
  set_thread_count(7);
  const std::vector<uint8_t> seven = lut_bytes(map, kLutDefaultSize);
  set_thread_count(before);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, seven);
}

}  // namespace
}  // namespace mbk
