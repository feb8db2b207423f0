// One corrupt fixture per validation finding: each is made from a valid file by one readable change, and
// validate_asset() must report exactly that finding's id (and no other error), while Asset::parse (what render,
// bake and synth read through) refuses every error among them with the documented exit code. Together with
// ValidationMessages.EveryIdHasAFixture this keeps the table of findings and the checks in step.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>

#include "formats/asset.h"
#include "formats/validate.h"
#include "tests/formats/asset_fixtures.h"
#include "tests/formats/colormap_fixtures.h"
#include "tests/formats/crease_fixtures.h"
#include "tests/formats/graph_fixtures.h"
#include "tests/formats/histogram_fixtures.h"
#include "tests/formats/lut_fixtures.h"
#include "tests/formats/moments_fixtures.h"
#include "tests/formats/neural_histogram_fixtures.h"
#include "tests/formats/rmq_fixtures.h"
#include "tests/formats/sh_fixtures.h"
#include "tests/formats/vmf_fixtures.h"

namespace mbk {
namespace {

using Bytes = std::vector<uint8_t>;
using test::entry_offset;
using test::reseal_header;
using test::reseal_section;
using test::section_data_offset;

struct CorruptCase {
  const char* name;
  int expected_id;
  std::function<Bytes()> make;
};
// gtest prints a failing parameter with this instead of its bytes.
void PrintTo(const CorruptCase& c, std::ostream* os) { *os << c.name << " (id " << c.expected_id << ")"; }

// First byte in a gap between regions of a valid file (the fixture always has one: 5x3 level data is not a
// multiple of 64 bytes).
uint64_t first_padding_byte(const Bytes& f) {
  uint64_t end0 = section_data_offset(f, 0) + load_le<uint64_t>(&f[entry_offset(f, 0) + 96]);
  return end0;  // level_0 is 180 bytes, the next section starts at the next multiple of 64
}

Bytes with_level_texel(size_t level, size_t texel, std::function<void(float*)> change) {
  Bytes f = test::valid_mip_bytes();
  if ((texel + 1) * 12 > load_le<uint64_t>(&f[entry_offset(f, level) + 96]))
    throw std::out_of_range("fixture texel outside level " + std::to_string(level));
  uint64_t off = section_data_offset(f, level) + texel * 12;
  float v[3];
  std::memcpy(v, &f[off], 12);
  change(v);
  std::memcpy(&f[off], v, 12);
  reseal_section(f, level);
  return f;
}

// A valid file whose metadata text (with `conventions` emptied, to make room) is changed by `edit`, resealed.
Bytes with_metadata_text(const std::function<void(std::string&)>& edit) {
  Bytes f = test::valid_mip_bytes();
  const uint64_t offset = load_le<uint64_t>(&f[header_field::metadata_offset]);
  auto m = nlohmann::json::parse(f.begin() + offset,
                                 f.begin() + offset + load_le<uint64_t>(&f[header_field::metadata_size]));
  m["conventions"] = nlohmann::json::object();
  std::string text = m.dump();
  edit(text);
  test::replace_metadata(f, text);
  return f;
}

std::vector<CorruptCase> corrupt_cases() {
  auto valid = [] { return test::valid_mip_bytes(); };
  auto meta_text = [](const Bytes& f) {
    return nlohmann::json::parse(std::string(f.begin() + load_le<uint64_t>(&f[24]),
                                             f.begin() + load_le<uint64_t>(&f[24]) + load_le<uint64_t>(&f[32])));
  };
  return {
      {"TooSmall", 1001,
       [&] {
         Bytes f = valid();
         f.resize(20);
         return f;
       }},
      {"BadMagic", 1002,
       [&] {
         Bytes f = valid();
         f[1] = 'X';
         return f;
       }},
      {"TextModeCrLfToLf", 1003,
       [&] {
         Bytes f = valid();
         f.erase(f.begin() + 4);
         return f;
       }},
      {"Extended", 1004,
       [&] {
         Bytes f = valid();
         f.push_back(0);
         return f;
       }},
      {"PaddingNotZero", 1005,
       [&] {
         Bytes f = valid();
         f[first_padding_byte(f)] = 1;
         return f;
       }},
      {"TrailingZeroBytes", 1007,  // validate accepted them before the spec said where a file ends
       [&] {
         Bytes f = valid();
         f.resize(f.size() + 64, 0);
         store_le<uint64_t>(&f[header_field::file_size], f.size());
         reseal_header(f);
         return f;
       }},
      {"NewerMajor", 2001,
       [&] {
         Bytes f = valid();
         store_le<uint16_t>(&f[8], 2);
         return f;
       }},
      {"MajorZero", 2002,
       [&] {
         Bytes f = valid();
         store_le<uint16_t>(&f[8], 0);
         return f;
       }},
      {"NewerMinor", 2003,
       [&] {
         Bytes f = valid();
         store_le<uint16_t>(&f[10], 7);
         reseal_header(f);
         return f;
       }},
      {"HeaderChecksum", 2004,
       [&] {
         Bytes f = valid();
         f[load_le<uint64_t>(&f[24]) + 3] ^= 0x20;
         return f;
       }},
      {"MetadataOutOfBounds", 2005,
       [&] {
         Bytes f = valid();
         store_le<uint64_t>(&f[32], f.size());
         return f;
       }},
      {"TableOutOfBounds", 2006,
       [&] {
         Bytes f = valid();
         store_le<uint32_t>(&f[48], 60000);
         return f;
       }},
      {"EntryTooSmall", 2007,
       [&] {
         Bytes f = valid();
         store_le<uint32_t>(&f[52], 64);
         return f;
       }},
      {"TooManySections", 2008,
       [&] {
         Bytes f = valid();
         store_le<uint32_t>(&f[48], 70000);
         return f;
       }},
      {"MetadataNotObject", 2009,
       [&] {
         Bytes f = valid();
         test::replace_metadata(f, "[1, 2]");
         return f;
       }},
      {"MetadataByteOrderMark", 2009,
       [&] { return with_metadata_text([](std::string& t) { t.insert(0, "\xEF\xBB\xBF"); }); }},
      {"MetadataDuplicateKey", 2015,  // the first "kind" of two; nlohmann alone would keep the last
       [&] { return with_metadata_text([](std::string& t) { t.insert(1, R"("kind":"mip",)"); }); }},
      {"MetadataNestedDuplicateKey", 2015,
       [&] {
         return with_metadata_text([](std::string& t) { t.insert(t.find(R"("parameters":{)") + 14, R"("width":5,)"); });
       }},
      {"MetadataMissingKey", 2010,
       [&] {
         Bytes f = valid();
         auto m = meta_text(f);
         m.erase("statistics");
         test::replace_metadata(f, m.dump());
         return f;
       }},
      {"UnknownKind", 2011,
       [&] {
         Bytes f = valid();
         store_le<uint32_t>(&f[12], 999);
         reseal_header(f);
         return f;
       }},
      {"KindMismatch", 2012,
       [&] {
         Bytes f = valid();
         auto m = meta_text(f);
         m["kind"] = "pim";
         test::replace_metadata(f, m.dump());
         return f;
       }},
      {"ProducerNotAnObject", 2014,
       [&] {
         Bytes f = valid();
         auto m = meta_text(f);
         m["producer"] = "microbake";
         test::replace_metadata(f, m.dump());
         return f;
       }},
      {"MetadataOverlapsTable", 2013,
       [&] {
         Bytes f = valid();
         store_le<uint64_t>(&f[40], 64);
         reseal_header(f);
         return f;
       }},
      {"BadSectionName", 3001,
       [&] {
         Bytes f = valid();
         f[entry_offset(f, 0)] = 'L';
         reseal_header(f);
         return f;
       }},
      {"DuplicateSection", 3002,
       [&] {
         Bytes f = valid();
         f[entry_offset(f, 1) + 6] = '0';
         reseal_header(f);
         return f;
       }},
      {"UnknownElementType", 3003,
       [&] {
         Bytes f = valid();
         store_le<uint32_t>(&f[entry_offset(f, 0) + 32], 99);
         reseal_header(f);
         return f;
       }},
      {"BadRank", 3004,
       [&] {
         Bytes f = valid();
         store_le<uint32_t>(&f[entry_offset(f, 0) + 36], 0);
         reseal_header(f);
         return f;
       }},
      {"ShapeOverflow", 3005,
       [&] {
         Bytes f = valid();
         store_le<uint64_t>(&f[entry_offset(f, 0) + 40], 1ull << 62);
         store_le<uint64_t>(&f[entry_offset(f, 0) + 48], 1ull << 62);
         reseal_header(f);
         return f;
       }},
      {"LengthMismatch", 3006,
       [&] {
         Bytes f = valid();
         store_le<uint64_t>(&f[entry_offset(f, 0) + 40], 4);
         reseal_header(f);
         return f;
       }},
      {"SectionOutOfBounds", 3007,
       [&] {
         Bytes f = valid();
         store_le<uint64_t>(&f[entry_offset(f, 0) + 88], align_up(f.size(), 64));
         reseal_header(f);
         return f;
       }},
      {"Misaligned", 3008,
       [&] {
         Bytes f = valid();
         uint64_t e = entry_offset(f, 0);
         store_le<uint64_t>(&f[e + 88], load_le<uint64_t>(&f[e + 88]) + 4);
         reseal_header(f);
         return f;
       }},
      {"SectionsOverlap", 3009,
       [&] {
         Bytes f = valid();
         store_le<uint64_t>(&f[entry_offset(f, 1) + 88], section_data_offset(f, 0));
         reseal_header(f);
         return f;
       }},
      {"EmptySectionInsideAnother", 3009,  // an empty section is a point: at a region's start or end, not inside
       [&] {
         AssetWriter w = test::mip_writer(5, 3);
         w.add<float>("empty", {0}, std::vector<float>{});
         Bytes f = w.serialize();
         // level_0 holds 180 bytes: 64 bytes in is strictly inside it
         store_le<uint64_t>(&f[entry_offset(f, 3) + entry_field::offset], section_data_offset(f, 0) + 64);
         reseal_header(f);
         return f;
       }},
      {"SectionChecksum", 3010,
       [&] {
         Bytes f = valid();
         f[section_data_offset(f, 0) + 5] ^= 1;
         return f;
       }},
      {"ReservedNotZero", 3011,
       [&] {
         Bytes f = valid();
         f[entry_offset(f, 0) + 120] = 1;
         reseal_header(f);
         return f;
       }},
      {"MissingRequiredSection", 3012,
       [&] {
         Bytes f = valid();
         f[entry_offset(f, 0) + 4] = 'x';
         reseal_header(f);
         return f;
       }},
      {"WrongSectionType", 3013,
       [&] {
         Bytes f = valid();
         store_le<uint32_t>(&f[entry_offset(f, 0) + 32], uint32_t(ElementType::u32));
         reseal_header(f);
         return f;
       }},
      {"UnknownSection", 3014,
       [&] {
         AssetWriter w = test::mip_writer(5, 3);
         w.add<uint8_t>("extra", {1}, std::vector<uint8_t>{7});
         return w.serialize();
       }},
      {"MipNonFinite", 11001, [&] { return with_level_texel(1, 1, [](float* v) { v[1] = std::nanf(""); }); }},
      {"MipLevelMissing", 11002, [] { return test::mip_writer(5, 3, 1).serialize(); }},
      {"MipLongerThanOne", 11003,
       [&] {
         return with_level_texel(1, 0, [](float* v) {
           v[0] = 0.9f;
           v[1] = 0.9f;
           v[2] = 0.9f;
         });
       }},
      {"MipLevel0NotUnit", 11004,
       [&] {
         return with_level_texel(0, 4, [](float* v) {
           for (int c = 0; c < 3; ++c) v[c] *= 0.9f;
         });
       }},
      {"MipParentNotMean", 11005, [&] { return with_level_texel(1, 1, [](float* v) { v[0] *= 0.95f; }); }},
      {"MipWidthMissing", 11006, [&] { return test::without_parameter(valid(), "width"); }},
      {"MipNegativeWidth", 11006, [] { return test::mip_writer(5, 3, 0, "width", -5).serialize(); }},
      {"MipWidthAbove32Bits", 11006,  // was read as 5, which made it valid
       [] { return test::mip_writer(5, 3, 0, "width", (uint64_t(1) << 32) + 5).serialize(); }},
      {"MipWidthNotAnInteger", 11006, [] { return test::mip_writer(5, 3, 0, "width", 5.0).serialize(); }},
      {"MipHeightAString", 11006, [] { return test::mip_writer(5, 3, 0, "height", "3").serialize(); }},
      {"MipLevelsMissing", 11006, [&] { return test::without_parameter(valid(), "levels"); }},
      {"MipLevelsDisagree", 11006, [] { return test::mip_writer(5, 3, 0, "levels", 2).serialize(); }},
      {"LutNonFinite", 20001, [] { return test::lut_with_value(0, 3, std::nanf("")); }},
      {"LutSizeOutOfRange", 20002, [] { return test::lut_with_size(1); }},
      {"LutShapeNotKnotRows", 20003, [] { return test::valid_lut_bytes(3); }},
      {"LutConstantChannelNotAtZero", 20004, [] { return test::lut_with_value(1, 1, 0.5f); }},
      {"LutKnotsNotIncreasing", 20005, [] { return test::lut_with_value(0, 4, -0.3f); }},  // x below knot 1's
      {"RmqBadParameters", 13001, [] { return test::rmq_with_parameter("patch", 3); }},
      {"RmqTableShape", 13002, [] { return test::rmq_with_parameter("bits", 8); }},  // the table is u16
      {"RmqRangeLoAboveHi", 13003, [] { return test::rmq_with_range_value(0, 1.0); }},
      {"RmqMinAboveMax", 13004,
       [] { return test::rmq_with_code(0, 4, 2, 0, [](uint16_t, uint16_t max) { return uint16_t(max + 1); }); }},
      {"RmqParentMissesAChild", 13005,
       [] { return test::rmq_with_code(1, 0, 0, 2, [](uint16_t min, uint16_t) { return uint16_t(min + 1); }); }},
      {"ShPrecisionNotF16OrF32", 14001, [] { return test::sh_with_parameter("precision", "f64"); }},
      {"ShLevelShapeDisagreesWithOrder", 14002, [] { return test::sh_with_parameter("order", 2); }},
      {"ShNonFinite", 14003, [] { return test::sh_with_value(1, 2, std::nanf("")); }},
      {"ShNormalNotUnit", 14004, [] { return test::sh_with_value(0, 2, 0.5f); }},
      {"ShDcNotY00", 14005, [] { return test::sh_with_value(1, 0, 0.3f); }},
      {"ShCoefficientAboveBasisMaximum", 14006, [] { return test::sh_with_value(1, 2, 0.6f); }},
      {"ShBand1NotMeanNormal", 14007, [] { return test::sh_with_value(1, 3, 0.13f); }},  // exact: c1 0.25 = 0.1221
      {"ShWindowAboveOne", 14008, [] { return test::sh_with_value(2, 1, 1.5f); }},
      {"VmfZeroLobes", 15001, [] { return test::vmf_with_parameter("lobes", 0); }},
      {"VmfFeatureShapeDisagrees", 15002, [] { return test::vmf_with_parameter("feature_channels", 2); }},
      {"VmfNonFinite", 15003, [] { return test::vmf_with_value(2, 1, std::nanf("")); }},
      {"VmfAmplitudesSumAboveOne", 15004, [] { return test::vmf_with_value(2, 0, 0.6f); }},
      {"VmfMeanLongerThanOne", 15005, [] { return test::vmf_with_value(2, 3, 0.6f); }},
      {"VmfFinestLobeNotUnit", 15006, [] { return test::vmf_with_value(0, 3, 0.9f); }},
      {"VmfMomentNotMeanNormal", 15007, [] { return test::vmf_with_value(2, 5, 0.29f); }},  // exact: 0.3
      {"VmfEmptyLobeWithFeature", 15008, [] { return test::vmf_with_value(1, 1, 0.5f); }},
      {"ColormapNonFinite", 17001, [] { return test::colormap_with_value(2, 7, std::nanf("")); }},
      {"ColormapSigmaMaxZero", 17002, [] { return test::colormap_with_parameter("sigma_max", 0.0); }},
      {"ColormapTableShapeDisagreesWithWidth", 17003, [] { return test::colormap_with_parameter("width", 6); }},
      {"ColormapKnotsDecrease", 17004, [] { return test::colormap_with_value(0, 1, -0.1f); }},
      {"ColormapRow0NotTheMap", 17005, [] { return test::colormap_with_table_delta(0, 2, 0, 0.01f); }},
      {"ColormapEntryAboveTheMapsMax", 17006, [] { return test::colormap_with_value(2, (2 * 5 + 2) * 3, 1.5f); }},
      {"ColormapEntryNotTheConvolution", 17007, [] { return test::colormap_with_table_delta(2, 2, 0, -0.001f); }},
      {"MomentsNonFinite", 18001, [] { return test::moments_with_element(1, 1, [](float) { return std::nanf(""); }); }},
      {"MomentsShiftNotANumber", 18002, [] { return test::moments_with_parameter("shift", "0.25"); }},
      {"MomentsLevelsDisagreeWithTheSize", 18002, [] { return test::moments_with_parameter("levels", 99); }},
      {"MomentsLevelShapeDisagreesWithWidth", 18003, [] { return test::moments_with_parameter("width", 6); }},
      {"MomentsLevel0SecondNotSquare", 18004,
       [] { return test::moments_with_element(0, 3, [](float m2) { return m2 * 1.01f + 1e-3f; }); }},
      {"MomentsNegativeVariance", 18005, [] { return test::moments_with_element(1, 1, [](float) { return 0.0f; }); }},
      {"MomentsParentNotMean", 18006,
       [] { return test::moments_with_element(1, 1, [](float m2) { return m2 + 0.01f; }); }},
      {"GraphSideNotAPowerOfTwo", 19001,
       [] { return test::graph_bytes([](test::GraphParts& p) { p.metadata["parameters"]["side"] = 6; }); }},
      {"GraphShapeDisagreesWithCandidates", 19002,
       [] { return test::graph_bytes([](test::GraphParts& p) { p.metadata["parameters"]["candidates"] = 2; }); }},
      {"GraphNonFiniteStack", 19003,
       [] { return test::graph_bytes([](test::GraphParts& p) { p.stacks[5] = std::nanf(""); }); }},
      {"GraphCandidateAtTheFinestLevel", 19004,
       [] { return test::graph_bytes([](test::GraphParts& p) { p.candidates[1] = 2; }); }},  // texel 0: (0, 2)
      {"GraphTransferWithinOneExemplar", 19005,
       [] { return test::graph_bytes([](test::GraphParts& p) { p.transfer[0] = 0.5f; }); }},  // (0, 0) -> E0_0
      {"GraphPcaBasisNotOrthonormal", 19006,
       [] { return test::graph_bytes([](test::GraphParts& p) { p.pca_basis[2 * 2 + 1] = 0.5f; }); }},
      // Found by tests/fuzz/fuzz_asset.cpp (corpus/asset/crash-graph-without-superexemplar): the layout looked the
      // graph-only metadata members up with json's const operator[], undefined for a missing key (an assertion in
      // the fuzz build).
      {"GraphSuperexemplarMissing", 19001,
       [] { return test::graph_bytes([](test::GraphParts& p) { p.metadata.erase("superexemplar"); }); }},
      {"GraphGraphMembersMissing", 19001,
       [] { return test::graph_bytes([](test::GraphParts& p) { p.metadata.erase("graph"); }); }},
      {"HistogramMethodNeural", 21001,
       [] { return test::histogram_with([](test::HistogramFixture& f) { f.parameters["method"] = "neural"; }); }},
      {"HistogramThetaBinningUnknown", 21001,
       [] {
         return test::histogram_with([](test::HistogramFixture& f) { f.parameters["theta_binning"] = "kmeans"; });
       }},
      {"HistogramMoreBinsThanRequested", 21001,
       [] {
         return test::histogram_with([](test::HistogramFixture& f) { f.parameters["theta_bins_requested"] = 1; });
       }},
      {"HistogramShapeDisagreesWithWidth", 21002,
       [] { return test::histogram_with([](test::HistogramFixture& f) { f.parameters["width"] = 4; }); }},
      {"HistogramThetaEdgesEndBelowTheHorizon", 21003,
       [] { return test::histogram_with([](test::HistogramFixture& f) { f.theta_edges[2] = 1.5; }); }},
      {"HistogramThetaEdgeNotTheMidpoint", 21004,
       [] { return test::histogram_with([](test::HistogramFixture& f) { f.theta_centres[0] = 0.3; }); }},
      {"HistogramPhiEdgesNotUniform", 21005,
       [] { return test::histogram_with([](test::HistogramFixture& f) { f.phi_edges[1] = 3.0; }); }},
      {"HistogramFirstRowNotZero", 21006,
       [] { return test::histogram_with([](test::HistogramFixture& f) { f.count(0, 1, 0) = 1; }); }},
      // Texel (1, 0)'s footprint reads S(1, 2) - S(1, 1): bin 0 drops to -1.
      {"HistogramNegativeCount", 21007,
       [] { return test::histogram_with([](test::HistogramFixture& f) { f.count(1, 2, 0) = 0; }); }},
      // Texel (0, 0)'s footprint counts bins 0 and 2: two texels in a one-texel footprint.
      {"HistogramCountsNotTheArea", 21008,
       [] { return test::histogram_with([](test::HistogramFixture& f) { f.count(1, 1, 2) = 1; }); }},
      {"NeuralHistogramMethodExact", 22001,
       [] {
         return test::neural_histogram_with([](test::NeuralHistogramFixture& f) { f.parameters["method"] = "exact"; });
       }},
      {"NeuralHistogramLevelsWrong", 22001,
       [] { return test::neural_histogram_with([](test::NeuralHistogramFixture& f) { f.parameters["levels"] = 2; }); }},
      {"NeuralHistogramShapeDisagreesWithWidth", 22002,
       [] { return test::neural_histogram_with([](test::NeuralHistogramFixture& f) { f.parameters["width"] = 4; }); }},
      {"NeuralHistogramMlpTooShort", 22002,
       [] { return test::neural_histogram_with([](test::NeuralHistogramFixture& f) { f.mlp.pop_back(); }); }},
      {"NeuralHistogramThetaEdgesEndBelowTheHorizon", 22003,
       [] { return test::neural_histogram_with([](test::NeuralHistogramFixture& f) { f.theta_edges[2] = 1.5; }); }},
      {"NeuralHistogramThetaEdgeNotTheMidpoint", 22004,
       [] { return test::neural_histogram_with([](test::NeuralHistogramFixture& f) { f.theta_centres[0] = 0.3; }); }},
      {"NeuralHistogramTexelBinOutOfRange", 22005,
       [] { return test::neural_histogram_with([](test::NeuralHistogramFixture& f) { f.texel_bins[4] = 4; }); }},
      {"NeuralHistogramInfiniteFeature", 22006,
       [] {
         return test::neural_histogram_with(
             [](test::NeuralHistogramFixture& f) { f.features[1] = Imath::half::posInf(); });
       }},
      {"NeuralHistogramNaNWeight", 22006,
       [] {
         return test::neural_histogram_with([](test::NeuralHistogramFixture& f) { f.mlp[50] = Imath::half::qNan(); });
       }},
      {"CreaseZeroWidth", 16001,
       [] {
         return test::crease_bytes({}, {{"width", 0}, {"height", 2}});
       }},
      {"CreaseShapeDisagreesWithWidth", 16002,
       [] {
         return test::crease_bytes({}, {{"width", 4}, {"height", 2}});
       }},
      {"CreaseNaNDistance", 16003,
       [] { return test::crease_bytes([](CreaseField& f) { f.distance[7] = std::nanf(""); }); }},
      {"CreaseCrossingOnACorner", 16004,
       [] { return test::crease_bytes([](CreaseField& f) { f.crossing_h[2] = 0.0f; }); }},
      {"CreaseThreeSegmentsInACell", 16005,
       [] { return test::crease_bytes([](CreaseField& f) { f.segments[f.cell_index(2, 1)] = 0x13; }); }},
      {"CreaseSegmentToUncrossedEdge", 16005,
       [] { return test::crease_bytes([](CreaseField& f) { f.segments[f.cell_index(2, 1)] = 1u << 5; }); }},
      {"CreaseNegativeDistance", 16006,
       [] { return test::crease_bytes([](CreaseField& f) { f.distance[3] = -0.5f; }); }},
      {"CreaseGradientNotUnit", 16007, [] { return test::crease_bytes([](CreaseField& f) { f.gradient[4] = 0.5f; }); }},
      {"CreaseSideZero", 16008, [] { return test::crease_bytes([](CreaseField& f) { f.side[5] = 0; }); }},
      {"CreaseNormalBelowHorizon", 16009,
       [] { return test::crease_bytes([](CreaseField& f) { f.normals[2] = -1.0f; }); }},
      {"CreaseJunctionWordWithoutRecord", 16010,
       [] { return test::crease_bytes([](CreaseField& f) { f.segments[f.cell_index(2, 1)] = kCreaseJunctionBit; }); }},
      {"CreaseJunctionWithOneSpoke", 16010,
       [] { return test::crease_bytes([](CreaseField& f) { test::add_crease_junction(f, 2, 1, 0.2f, 0.5f, 0x01); }); }},
      {"CreaseJunctionSpokeToUncrossedEdge", 16010,
       [] { return test::crease_bytes([](CreaseField& f) { test::add_crease_junction(f, 2, 1, 0.2f, 0.5f, 0x03); }); }},
      {"CreaseJunctionPointOutsideTheEdgePoints", 16010,
       [] {
         return test::crease_bytes([](CreaseField& f) { test::add_crease_junction(f, 2, 1, 0.95f, 0.05f, 0x05); });
       }},
  };
}

class CorruptFixture : public ::testing::TestWithParam<CorruptCase> {};

TEST_P(CorruptFixture, ReportsExactlyItsFinding) {
  const CorruptCase& c = GetParam();
  Bytes bytes = c.make();
  std::vector<Finding> findings = validate_asset(bytes);
  std::set<int> ids;
  const MessageInfo* info = nullptr;
  for (const auto& m : all_messages())
    if (m.id == c.expected_id) info = &m;
  ASSERT_NE(info, nullptr) << "fixture names an id that is not in the table";
  for (const Finding& f : findings)
    if (f.severity == Severity::error || info->severity == Severity::warning) ids.insert(f.id);
  EXPECT_EQ(ids, std::set<int>{c.expected_id}) << (findings.empty() ? "no findings" : findings.front().message);

  if (info->severity == Severity::warning) {
    EXPECT_NO_THROW(Asset::parse(bytes, "fixture"));
  } else {  // the reader checks what validate checks, kind invariants included: render and bake never use it
    try {
      Asset::parse(bytes, "fixture");
      ADD_FAILURE() << "reader accepted a corrupt file";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), c.expected_id == msg::newer_major.id ? ExitCode::unsupported : ExitCode::invalid_input);
      EXPECT_NE(std::string(e.what()).find(std::to_string(c.expected_id)), std::string::npos) << e.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Findings, CorruptFixture, ::testing::ValuesIn(corrupt_cases()),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(ValidationMessages, IdsUniqueAndGroupedByThousand) {
  std::set<int> seen;
  for (const auto& m : all_messages()) {
    EXPECT_TRUE(seen.insert(m.id).second) << "duplicate id " << m.id;
    bool grouped = (m.id >= 1000 && m.id < 4000) || m.id >= 11000;
    EXPECT_TRUE(grouped) << m.id;
  }
}

TEST(ValidationMessages, EveryIdHasAFixture) {
  // Findings about a file rather than its bytes have a CLI case instead (tests/cli/cases.json).
  std::set<int> covered = {msg::file_unreadable.id};  // ValidateMissingFileJson, ValidateFolderJson
  for (const auto& c : corrupt_cases()) covered.insert(c.expected_id);
  for (const auto& m : all_messages()) EXPECT_TRUE(covered.count(m.id)) << "no corrupt fixture for id " << m.id;
}

TEST(ValidationMessages, NewerMajorNamesBothVersions) {
  Bytes f = test::valid_mip_bytes();
  store_le<uint16_t>(&f[8], 3);
  store_le<uint16_t>(&f[10], 2);
  try {
    Asset::parse(f, "x.mbk");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::unsupported);
    EXPECT_NE(e.message().find("3.2"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("1.0"), std::string::npos) << e.message();
  }
}

TEST(ValidationMessages, ValidFileHasNoFindings) {
  for (auto [w, h] : {std::pair{1u, 1u}, {5u, 3u}, {1u, 9u}, {16u, 16u}, {33u, 17u}}) {
    auto findings = validate_asset(test::valid_mip_bytes(w, h));
    EXPECT_TRUE(findings.empty()) << w << "x" << h << ": " << findings.front().message;
  }
}

}  // namespace
}  // namespace mbk
