// Serializes the .mbk container, version 1.0 (formats/SPEC.md).
#include "formats/asset_writer.h"

#include <array>
#include <cstring>

#include "formats/asset_kind.h"
#include "formats/atomic_file.h"
#include "formats/byte_io.h"
#include "formats/version.h"

namespace mbk {

struct AssetWriter::MemoryOutput : Output {
  std::vector<uint8_t> bytes;
  void append(std::span<const uint8_t> b) override { bytes.insert(bytes.end(), b.begin(), b.end()); }
  void overwrite_head(std::span<const uint8_t> head) override { std::memcpy(bytes.data(), head.data(), head.size()); }
};

struct AssetWriter::FileOutput : Output {
  AtomicFile& file;
  explicit FileOutput(AtomicFile& f) : file(f) {}
  void append(std::span<const uint8_t> b) override { file.append(b); }
  void overwrite_head(std::span<const uint8_t> head) override { file.overwrite(0, head); }
};

AssetWriter::AssetWriter(std::string_view kind_name, nlohmann::json metadata) : metadata_(std::move(metadata)) {
  const AssetKind* kind = find_kind(kind_name);
  if (!kind) throw Error(ExitCode::runtime_failure, "internal: unknown asset kind '" + std::string(kind_name) + "'");
  kind_id_ = kind->id;
  if (!metadata_.is_object()) throw Error(ExitCode::runtime_failure, "internal: metadata must be a JSON object");
  for (const char* key : {"inputs", "parameters", "conventions", "statistics"})
    if (!metadata_.contains(key))
      throw Error(ExitCode::runtime_failure, std::string("internal: metadata lacks '") + key + "'");
  metadata_["kind"] = std::string(kind_name);
  metadata_["producer"] = {{"name", "microbake"}, {"version", microbake_version()}};
}

void AssetWriter::add_bytes(const std::string& name, ElementType type, std::vector<uint64_t> shape,
                            std::span<const uint8_t> bytes) {
  auto copy = std::make_shared<const std::vector<uint8_t>>(bytes.begin(), bytes.end());
  PendingSection s;
  s.bytes = std::span<const uint8_t>(*copy);
  s.owner = std::move(copy);
  add_section(name, type, std::move(shape), std::move(s));
}

void AssetWriter::add_produced(const std::string& name, ElementType type, std::vector<uint64_t> shape,
                               SectionProducer produce) {
  PendingSection s;
  s.produce = std::move(produce);
  add_section(name, type, std::move(shape), std::move(s));
}

void AssetWriter::add_section(const std::string& name, ElementType type, std::vector<uint64_t> shape,
                              PendingSection s) {
  if (!is_valid_section_name(name))
    throw Error(ExitCode::runtime_failure, "internal: invalid section name '" + name + "'");
  for (const auto& other : sections_)
    if (other.info.name == name) throw Error(ExitCode::runtime_failure, "internal: duplicate section '" + name + "'");
  if (shape.empty() || shape.size() > kMaxRank)
    throw Error(ExitCode::runtime_failure, "internal: rank outside 1..6 for '" + name + "'");
  uint64_t count = 1;
  for (uint64_t d : shape)
    if (__builtin_mul_overflow(count, d, &count))
      throw Error(ExitCode::runtime_failure, "internal: shape overflow for '" + name + "'");
  uint64_t length = 0;
  if (__builtin_mul_overflow(count, element_size(static_cast<uint32_t>(type)), &length) ||
      (!s.produce && length != s.bytes.size()))
    throw Error(ExitCode::runtime_failure, "internal: byte length does not match the shape of '" + name + "'");
  s.info.name = name;
  s.info.type = type;
  s.info.shape = std::move(shape);
  s.info.byte_length = length;
  if (!s.produce) s.info.checksum = checksum_of(s.bytes.data(), s.bytes.size());
  sections_.push_back(std::move(s));
}

AssetWriter::Placement AssetWriter::place() const {
  Placement p;
  p.metadata = metadata_.dump();  // keys sorted (std::map): byte-identical for identical content
  p.table_offset = align_up(kHeaderSize + p.metadata.size(), kSectionAlignment);
  const uint64_t table_end = p.table_offset + uint64_t(kSectionEntrySize) * sections_.size();
  uint64_t cursor = align_up(table_end, kSectionAlignment);
  for (const auto& s : sections_) {
    p.offsets.push_back(cursor);
    cursor = align_up(cursor + s.info.byte_length, kSectionAlignment);
  }
  // The file ends right after the last section's data (no trailing padding).
  p.file_size = sections_.empty() ? table_end : p.offsets.back() + sections_.back().info.byte_length;
  p.head_size = sections_.empty() ? p.file_size : p.offsets.front();
  return p;
}

std::vector<uint8_t> AssetWriter::head(const Placement& p, const std::vector<uint64_t>& checksums) const {
  std::vector<uint8_t> out(p.head_size, 0);
  std::copy(p.metadata.begin(), p.metadata.end(), out.begin() + kHeaderSize);
  for (size_t i = 0; i < sections_.size(); ++i) {
    SectionInfo entry = sections_[i].info;
    entry.offset = p.offsets[i];
    entry.checksum = checksums[i];
    store_section_entry(&out[p.table_offset + i * kSectionEntrySize], entry);
  }
  ContainerHeader h;
  h.kind = kind_id_;
  h.file_size = p.file_size;
  h.metadata_offset = kHeaderSize;
  h.metadata_size = p.metadata.size();
  h.section_table_offset = p.table_offset;
  h.section_count = static_cast<uint32_t>(sections_.size());
  store_header(out.data(), h);  // the checksum covers the header's first bytes, so it is stored last
  store_le<uint64_t>(&out[header_field::checksum],
                     header_checksum(out.data(), kHeaderSize, p.metadata.size(), p.table_offset,
                                     uint64_t(kSectionEntrySize) * sections_.size()));
  return out;
}

void AssetWriter::emit(Output& out) const {
  static const std::array<uint8_t, kSectionAlignment> zeros{};
  const Placement p = place();
  out.append(std::vector<uint8_t>(p.head_size, 0));
  std::vector<uint64_t> checksums;
  for (size_t i = 0; i < sections_.size(); ++i) {
    const PendingSection& s = sections_[i];
    if (i > 0) {
      const uint64_t previous_end = p.offsets[i - 1] + sections_[i - 1].info.byte_length;
      out.append(std::span<const uint8_t>(zeros.data(), p.offsets[i] - previous_end));
    }
    if (!s.produce) {
      out.append(s.bytes);
      checksums.push_back(s.info.checksum);
      continue;
    }
    StreamedChecksum checksum;
    uint64_t produced = 0;
    s.produce([&](std::span<const uint8_t> piece) {
      if (piece.size() > s.info.byte_length - produced)
        throw Error(ExitCode::runtime_failure, "internal: section '" + s.info.name + "' produced too many bytes");
      checksum.update(piece.data(), piece.size());
      out.append(piece);
      produced += piece.size();
    });
    if (produced != s.info.byte_length)
      throw Error(ExitCode::runtime_failure, "internal: section '" + s.info.name + "' produced too few bytes");
    checksums.push_back(checksum.digest());
  }
  out.overwrite_head(head(p, checksums));
}

std::vector<uint8_t> AssetWriter::serialize() const {
  MemoryOutput out;
  out.bytes.reserve(place().file_size);
  emit(out);
  return std::move(out.bytes);
}

uint64_t AssetWriter::file_size() const { return place().file_size; }

void AssetWriter::write(const std::filesystem::path& path) const {
  AtomicFile file(path);
  FileOutput out(file);
  emit(out);
  file.commit();
}

}  // namespace mbk
