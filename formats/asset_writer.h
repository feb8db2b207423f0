// Builds an .mbk file (formats/SPEC.md): metadata plus typed, shaped sections, serialized with aligned
// offsets and XXH3-64 checksums, and written atomically (temporary file, flush, rename).
#pragma once

#include <cstdint>
#include <filesystem>
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
    const std::span<const uint8_t> bytes(reinterpret_cast<const uint8_t*>(owned->data()), owned->size() * sizeof(T));
    add_section(name, type, std::move(shape), bytes, std::move(owned));
  }
  // Throws Error(runtime_failure) on a bad name, duplicate, rank or a length that does not match the shape.
  void add_bytes(const std::string& name, ElementType type, std::vector<uint64_t> shape,
                 std::span<const uint8_t> bytes);

  // The file's bytes in one buffer.
  std::vector<uint8_t> serialize() const;
  // The file's size in bytes.
  uint64_t file_size() const;
  // Writes the file atomically, section by section (no whole-file buffer). Throws Error(io_failure).
  void write(const std::filesystem::path& path) const;

 private:
  struct PendingSection {
    SectionInfo info;
    std::span<const uint8_t> bytes;
    std::shared_ptr<const void> owner;  // keeps `bytes` alive
  };
  // The file as consecutive pieces: header, metadata and section table in one, then each section's bytes and
  // its zero padding.
  struct Layout {
    std::vector<uint8_t> head;
    std::vector<std::span<const uint8_t>> pieces;
    uint64_t file_size = 0;
  };
  void add_section(const std::string& name, ElementType type, std::vector<uint64_t> shape,
                   std::span<const uint8_t> bytes, std::shared_ptr<const void> owner);
  Layout layout() const;
  uint32_t kind_id_;
  nlohmann::json metadata_;
  std::vector<PendingSection> sections_;
};

}  // namespace mbk
