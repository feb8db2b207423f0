// The container round-trips every element type, shape and metadata exactly, lays sections out aligned,
// and serializes identical content to identical bytes.
#include <gtest/gtest.h>

#include <Imath/half.h>

#include "formats/asset.h"
#include "formats/asset_writer.h"
#include "formats/atomic_file.h"
#include "libbake/core/uninitialized_vector.h"
#include "tests/formats/asset_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

// The `mip` kind's name is used as a carrier; its invariants are not run by Asset::parse, and the extra
// sections are allowed (readers ignore unknown sections).
template <typename T>
std::vector<T> pattern(size_t n) {
  std::vector<T> v(n);
  for (size_t i = 0; i < n; ++i)
    v[i] = static_cast<T>(static_cast<double>((i * 37) % 251) - (std::is_signed_v<T> ? 100 : 0));
  return v;
}

template <typename T>
void expect_round_trip(const std::vector<uint64_t>& shape) {
  size_t n = 1;
  for (auto d : shape) n *= d;
  auto data = pattern<T>(n);
  AssetWriter w = test::mip_writer(2, 2);
  w.add<T>("payload", shape, data);
  Asset a = Asset::parse(w.serialize(), "memory");
  const SectionInfo& s = a.section("payload");
  EXPECT_EQ(s.type, ElementOf<T>::value);
  EXPECT_EQ(s.shape, shape);
  EXPECT_EQ(s.offset % kSectionAlignment, 0u);
  EXPECT_EQ(a.read<T>("payload"), data);
}

TEST(ContainerRoundTrip, EveryElementTypeAndRank) {
  expect_round_trip<uint8_t>({7});
  expect_round_trip<int8_t>({3, 5});
  expect_round_trip<uint16_t>({2, 3, 4});
  expect_round_trip<int16_t>({1, 2, 3, 4});
  expect_round_trip<uint32_t>({2, 1, 2, 1, 3});
  expect_round_trip<int32_t>({1, 1, 1, 1, 1, 9});
  expect_round_trip<uint64_t>({5});
  expect_round_trip<int64_t>({4, 4});
  expect_round_trip<Imath::half>({3, 3});
  expect_round_trip<float>({64, 3});
  expect_round_trip<double>({33});
}

TEST(ContainerRoundTrip, EmptySectionAndFloatConversion) {
  AssetWriter w = test::mip_writer(1, 1);
  w.add<float>("empty", {0, 3}, std::vector<float>{});
  std::vector<Imath::half> h = {Imath::half(0.5f), Imath::half(-2.0f), Imath::half(65504.0f)};
  w.add<Imath::half>("halves", {3}, h);
  w.add<double>("doubles", {2}, std::vector<double>{1e-300, -3.25});
  Asset a = Asset::parse(w.serialize(), "memory");
  EXPECT_EQ(a.section("empty").byte_length, 0u);
  EXPECT_EQ(a.read_as_float("halves"), (std::vector<float>{0.5f, -2.0f, 65504.0f}));
  EXPECT_EQ(a.read_as_float("doubles")[1], -3.25f);
  EXPECT_THROW(a.read<double>("halves"), Error);
  EXPECT_THROW(a.section("absent"), Error);
}

TEST(ContainerRoundTrip, MetadataPreservedWithProducerAndKind) {
  nlohmann::json meta = test::mip_metadata(2, 2, 2);
  meta["statistics"]["note"] = "ünïcode ✓";
  meta["parameters"]["big"] = 18446744073709551615ull;
  AssetWriter w("mip", meta);
  w.add<float>("level_0", {2, 2, 3}, test::unit_normals(2, 2));
  // The container alone: this two-level mip has one level, which the kind's invariants (Asset::parse) refuse.
  Asset a = Asset::parse_structure(w.serialize(), "memory");
  EXPECT_EQ(a.metadata()["kind"], "mip");
  EXPECT_EQ(a.metadata()["producer"]["name"], "microbake");
  EXPECT_EQ(a.metadata()["statistics"]["note"], "ünïcode ✓");
  EXPECT_EQ(a.metadata()["parameters"]["big"].get<uint64_t>(), 18446744073709551615ull);
  EXPECT_EQ(a.header().major, kFormatMajor);
  EXPECT_EQ(a.header().minor, kFormatMinor);
  EXPECT_EQ(a.kind().name, "mip");
}

TEST(ContainerRoundTrip, IdenticalContentGivesIdenticalBytes) {
  EXPECT_EQ(test::valid_mip_bytes(7, 5), test::valid_mip_bytes(7, 5));
  EXPECT_NE(test::valid_mip_bytes(7, 5), test::valid_mip_bytes(5, 7));
}

// Sections taken over (moved in, any allocator) and copied in give the same file, and write() streams exactly
// the bytes serialize() returns: odd lengths (padding between sections), an empty section, u8 and f32.
TEST(ContainerRoundTrip, TakenOverSectionsAndStreamedWriteGiveTheSerializedBytes) {
  auto fill = [](AssetWriter& w, bool move) {
    std::vector<uint8_t> odd = pattern<uint8_t>(101);
    std::vector<float> floats = pattern<float>(37);
    UninitializedVector<uint8_t> raw(5);
    for (size_t i = 0; i < raw.size(); ++i) raw[i] = uint8_t(200 + i);
    if (move) {
      w.add_bytes("odd", ElementType::u8, {101}, std::move(odd));
      w.add("empty", {0}, std::vector<float>());
      w.add("floats", {37}, std::move(floats));
      w.add_bytes("raw", ElementType::u8, {5}, std::move(raw));
    } else {
      w.add("odd", {101}, odd);
      w.add<float>("empty", {0}, std::span<const float>());
      w.add("floats", {37}, floats);
      w.add_bytes("raw", ElementType::u8, {5}, std::span<const uint8_t>(raw.data(), raw.size()));
    }
  };
  AssetWriter moved = test::mip_writer(2, 2), copied = test::mip_writer(2, 2);
  fill(moved, true);
  fill(copied, false);
  const std::vector<uint8_t> bytes = copied.serialize();
  EXPECT_EQ(moved.serialize(), bytes);
  EXPECT_EQ(moved.file_size(), bytes.size());
  test::ScratchDir dir("streamed_write");
  moved.write(dir.path() / "streamed.mbk");
  EXPECT_EQ(read_file_bytes(dir.path() / "streamed.mbk"), bytes);
  const Asset a = Asset::parse(bytes, "memory");
  EXPECT_EQ(a.read<uint8_t>("odd"), pattern<uint8_t>(101));
  EXPECT_EQ(a.read<float>("floats"), pattern<float>(37));
  EXPECT_EQ(a.read<uint8_t>("raw"), (std::vector<uint8_t>{200, 201, 202, 203, 204}));
}

// A produced section (AssetWriter::add_produced) gives the file a held section gives, whatever the pieces it is
// emitted in (empty, odd, one byte), before and after held sections, and on every call (serialize, then write).
TEST(ContainerRoundTrip, ProducedSectionsGiveTheBytesOfHeldOnes) {
  const std::vector<uint16_t> codes = pattern<uint16_t>(1001);
  const std::vector<uint8_t> tail = pattern<uint8_t>(13);
  const std::span<const uint8_t> code_bytes(reinterpret_cast<const uint8_t*>(codes.data()), codes.size() * 2);
  AssetWriter held = test::mip_writer(3, 2), produced = test::mip_writer(3, 2);
  held.add("codes", {7, 11, 13}, codes);
  held.add("tail", {13}, tail);
  int calls = 0;
  produced.add_produced("codes", ElementType::u16, {7, 11, 13}, [&](const AssetWriter::SectionSink& emit) {
    ++calls;
    const size_t sizes[] = {0, 1, 777, 3};
    for (size_t at = 0, i = 0; at < code_bytes.size(); ++i) {
      const size_t piece = std::min(code_bytes.size() - at, sizes[i % 4]);
      emit(code_bytes.subspan(at, piece));
      at += piece;
    }
  });
  produced.add_produced("tail", ElementType::u8, {13}, [&](const AssetWriter::SectionSink& emit) { emit(tail); });
  const std::vector<uint8_t> bytes = held.serialize();
  EXPECT_EQ(produced.file_size(), bytes.size());
  EXPECT_EQ(produced.serialize(), bytes);
  test::ScratchDir dir("produced_write");
  produced.write(dir.path() / "produced.mbk");
  EXPECT_EQ(read_file_bytes(dir.path() / "produced.mbk"), bytes);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(Asset::parse(bytes, "memory").read<uint16_t>("codes"), codes);
}

// A producer that emits too few or too many bytes, or throws, is an internal error, and write() leaves no file
// (nor its temporary) behind.
TEST(ContainerRoundTrip, ProducerOfTheWrongLengthOrThatThrowsLeavesNoFile) {
  const std::vector<uint8_t> ten(10, 7);
  const std::vector<AssetWriter::SectionProducer> producers = {
      [&](const AssetWriter::SectionSink& emit) { emit(std::span(ten).first(9)); },
      [&](const AssetWriter::SectionSink& emit) { emit(ten), emit(std::span(ten).first(1)); },
      [&](const AssetWriter::SectionSink& emit) {
        emit(std::span(ten).first(5));
        throw Error(ExitCode::io_failure, "input vanished", "x.png");
      }};
  for (size_t i = 0; i < producers.size(); ++i) {
    SCOPED_TRACE(i);
    AssetWriter w = test::mip_writer(2, 2);
    w.add_produced("ten", ElementType::u8, {10}, producers[i]);
    EXPECT_THROW(w.serialize(), Error);
    test::ScratchDir dir("produced_failure");
    try {
      w.write(dir.path() / "out.mbk");
      ADD_FAILURE() << "write() succeeded";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), i < 2 ? ExitCode::runtime_failure : ExitCode::io_failure);
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
  }
}

TEST(ContainerRoundTrip, WriterRejectsMalformedSections) {
  AssetWriter w = test::mip_writer(1, 1);
  std::vector<float> three(3);
  EXPECT_THROW(w.add<float>("Bad-Name", {3}, three), Error);
  EXPECT_THROW(w.add<float>("level_0", {3}, three), Error);              // duplicate
  EXPECT_THROW(w.add<float>("x", {2}, three), Error);                    // length mismatch
  EXPECT_THROW(w.add<float>("y", {}, three), Error);                     // rank 0
  EXPECT_THROW(w.add<float>("z", {1, 1, 1, 1, 1, 1, 3}, three), Error);  // rank 7
  EXPECT_THROW(AssetWriter("no-such-kind", test::mip_metadata(1, 1, 1)), Error);
}

}  // namespace
}  // namespace mbk
