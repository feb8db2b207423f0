// Builds an .mbk file (formats/SPEC.md): metadata plus typed, shaped sections, serialized with aligned
// offsets and XXH3-64 checksums, and written atomically (temporary file, flush, rename). A section is either
// bytes the writer holds, or produced piece by piece while the file is written (a bake whose output should not
// be in memory at once); the header and section table, which hold the checksums, are written last, over the
// place kept for them at the start of the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/container_layout.h"
#include "formats/error.h"

namespace mbk {

class AssetWriter {
 public:
  // kind_name must be registered in formats/asset_kind.h. The metadata must hold the keys "inputs",
  // "parameters", "conventions" and "statistics"; the writer adds "kind" and "producer".
  AssetWriter(std::string_view kind_name, nlohmann::json metadata);

  // Copies the data into the writer.
  template <typename T>
  void add(const std::string& name, std::vector<uint64_t> shape, std::span<const T> data) {
    add_bytes(name, ElementOf<T>::value, std::move(shape),
              std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(data.data()), data.size_bytes()));
  }
  template <typename T>
  void add(const std::string& name, std::vector<uint64_t> shape, const std::vector<T>& data) {
    add(name, std::move(shape), std::span<const T>(data));
  }
  // Take the data over without copying it (the large sections of a bake: the file's bytes are then in memory
  // once, and write() streams them out). Any allocator; add_bytes with any element type whose in-memory
  // bytes are the section's (floats, packed Eigen vectors).
  template <typename T, typename A>
  void add(const std::string& name, std::vector<uint64_t> shape, std::vector<T, A>&& data) {
    add_bytes(name, ElementOf<T>::value, std::move(shape), std::move(data));
  }
  template <typename T, typename A>
  void add_bytes(const std::string& name, ElementType type, std::vector<uint64_t> shape, std::vector<T, A>&& data) {
    auto owned = std::make_shared<const std::vector<T, A>>(std::move(data));
    PendingSection s;
    s.bytes = std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(owned->data()), owned->size() * sizeof(T));
    s.owner = std::move(owned);
    add_section(name, type, std::move(shape), std::move(s));
  }
  // Throws Error(runtime_failure) on a bad name, duplicate, rank or a length that does not match the shape.
  void add_bytes(const std::string& name, ElementType type, std::vector<uint64_t> shape,
                 std::span<const uint8_t> bytes);

  // A section produced while the file is written: every serialize() and write() calls `produce` once, which hands
  // `emit` the section's bytes in order, in pieces of any size; they must add up to exactly the shape's length
  // (Error(runtime_failure) otherwise, and nothing is written). An exception from `produce` leaves no file.
  using SectionSink = std::function<void(std::span<const uint8_t>)>;
  using SectionProducer = std::function<void(const SectionSink& emit)>;
  void add_produced(const std::string& name, ElementType type, std::vector<uint64_t> shape, SectionProducer produce);

  // The file's bytes in one buffer.
  std::vector<uint8_t> serialize() const;
  // The file's size in bytes.
  uint64_t file_size() const;
  // Writes the file atomically, section by section (no whole-file buffer). Throws Error(io_failure).
  void write(const std::filesystem::path& path) const;

 private:
  struct PendingSection {
    SectionInfo info;                   // the checksum is known here for held bytes, computed when produced
    std::span<const uint8_t> bytes;     // held bytes, or
    SectionProducer produce;            // the producer
    std::shared_ptr<const void> owner;  // keeps `bytes` alive
  };
  // Where everything goes: the metadata text, the section table's offset, each section's offset, the size of the
  // head (header, metadata and section table, up to the first section) and of the file.
  struct Placement {
    std::string metadata;
    uint64_t table_offset = 0, head_size = 0, file_size = 0;
    std::vector<uint64_t> offsets;
  };
  // The two outputs of emit(): a byte buffer, or an atomic file.
  struct Output {
    virtual void append(std::span<const uint8_t> bytes) = 0;
    virtual void overwrite_head(std::span<const uint8_t> head) = 0;
    virtual ~Output() = default;
  };
  struct MemoryOutput;
  struct FileOutput;
  void add_section(const std::string& name, ElementType type, std::vector<uint64_t> shape, PendingSection section);
  Placement place() const;
  std::vector<uint8_t> head(const Placement& p, const std::vector<uint64_t>& checksums) const;
  // The file from start to end: a zero head, each section (held or produced) with its padding, then the head.
  void emit(Output& out) const;
  uint32_t kind_id_;
  nlohmann::json metadata_;
  std::vector<PendingSection> sections_;
};

}  // namespace mbk
