// Serializes the .mbk container, version 1.0 (formats/SPEC.md).
#include "formats/asset_writer.h"

#include <array>

#include "formats/asset_kind.h"
#include "formats/version.h"
#include "formats/atomic_file.h"
#include "formats/byte_io.h"

namespace mbk {

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
  const std::span<const uint8_t> owned(*copy);
  add_section(name, type, std::move(shape), owned, std::move(copy));
}

void AssetWriter::add_section(const std::string& name, ElementType type, std::vector<uint64_t> shape,
                              std::span<const uint8_t> bytes, std::shared_ptr<const void> owner) {
  if (!is_valid_section_name(name))
    throw Error(ExitCode::runtime_failure, "internal: invalid section name '" + name + "'");
  for (const auto& s : sections_)
    if (s.info.name == name) throw Error(ExitCode::runtime_failure, "internal: duplicate section '" + name + "'");
  if (shape.empty() || shape.size() > kMaxRank)
    throw Error(ExitCode::runtime_failure, "internal: rank outside 1..6 for '" + name + "'");
  uint64_t count = 1;
  for (uint64_t d : shape)
    if (__builtin_mul_overflow(count, d, &count))
      throw Error(ExitCode::runtime_failure, "internal: shape overflow for '" + name + "'");
  if (count * element_size(static_cast<uint32_t>(type)) != bytes.size())
    throw Error(ExitCode::runtime_failure, "internal: byte length does not match the shape of '" + name + "'");
  PendingSection s;
  s.info.name = name;
  s.info.type = type;
  s.info.shape = std::move(shape);
  s.info.byte_length = bytes.size();
  s.info.checksum = checksum_of(bytes.data(), bytes.size());
  s.bytes = bytes;
  s.owner = std::move(owner);
  sections_.push_back(std::move(s));
}

AssetWriter::Layout AssetWriter::layout() const {
  static const std::array<uint8_t, kSectionAlignment> zeros{};
  const std::string meta = metadata_.dump();  // keys sorted (std::map): byte-identical for identical content
  const uint64_t meta_offset = kHeaderSize;
  const uint64_t table_offset = align_up(meta_offset + meta.size(), kSectionAlignment);
  const uint64_t table_size = uint64_t(kSectionEntrySize) * sections_.size();
  uint64_t cursor = align_up(table_offset + table_size, kSectionAlignment);
  std::vector<uint64_t> offsets;
  for (const auto& s : sections_) {
    offsets.push_back(cursor);
    cursor = align_up(cursor + s.bytes.size(), kSectionAlignment);
  }
  Layout l;
  // The file ends right after the last section's data (no trailing padding).
  l.file_size = sections_.empty() ? table_offset + table_size : offsets.back() + sections_.back().bytes.size();
  l.head.assign(sections_.empty() ? l.file_size : offsets.front(), 0);
  std::vector<uint8_t>& out = l.head;
  std::copy(meta.begin(), meta.end(), out.begin() + meta_offset);
  for (size_t i = 0; i < sections_.size(); ++i) {
    SectionInfo entry = sections_[i].info;
    entry.offset = offsets[i];
    store_section_entry(&out[table_offset + i * kSectionEntrySize], entry);
  }
  ContainerHeader h;
  h.kind = kind_id_;
  h.file_size = l.file_size;
  h.metadata_offset = meta_offset;
  h.metadata_size = meta.size();
  h.section_table_offset = table_offset;
  h.section_count = static_cast<uint32_t>(sections_.size());
  store_header(out.data(), h);  // the checksum covers the header's first bytes, so it is stored last
  store_le<uint64_t>(&out[header_field::checksum],
                     header_checksum(out.data(), meta_offset, meta.size(), table_offset, table_size));
  l.pieces.push_back(l.head);
  for (size_t i = 0; i < sections_.size(); ++i) {
    l.pieces.push_back(sections_[i].bytes);
    const uint64_t end = offsets[i] + sections_[i].bytes.size();
    if (i + 1 < sections_.size()) l.pieces.push_back(std::span<const uint8_t>(zeros.data(), offsets[i + 1] - end));
  }
  return l;
}

std::vector<uint8_t> AssetWriter::serialize() const {
  const Layout l = layout();
  std::vector<uint8_t> out;
  out.reserve(l.file_size);
  for (std::span<const uint8_t> piece : l.pieces) out.insert(out.end(), piece.begin(), piece.end());
  return out;
}

uint64_t AssetWriter::file_size() const { return layout().file_size; }

void AssetWriter::write(const std::filesystem::path& path) const {
  AtomicFile file(path);
  file.write_all(layout().pieces);
  file.commit();
}

}  // namespace mbk
