// Builds an .mbk file (formats/SPEC.md): metadata plus typed, shaped sections, serialized with aligned
// offsets and XXH3-64 checksums, and written atomically (temporary file, flush, rename).
#pragma once

#include <cstdint>
#include <filesystem>
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

  template <typename T>
  void add(const std::string& name, std::vector<uint64_t> shape, std::span<const T> data) {
    add_bytes(name, ElementOf<T>::value, std::move(shape),
              std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(data.data()), data.size_bytes()));
  }
  template <typename T>
  void add(const std::string& name, std::vector<uint64_t> shape, const std::vector<T>& data) {
    add(name, std::move(shape), std::span<const T>(data));
  }
  // Throws Error(runtime_failure) on a bad name, duplicate, rank or a length that does not match the shape.
  void add_bytes(const std::string& name, ElementType type, std::vector<uint64_t> shape,
                 std::span<const uint8_t> bytes);

  std::vector<uint8_t> serialize() const;
  // Serializes and writes atomically. Throws Error(io_failure).
  void write(const std::filesystem::path& path) const;

 private:
  struct PendingSection {
    SectionInfo info;
    std::vector<uint8_t> bytes;
  };
  uint32_t kind_id_;
  nlohmann::json metadata_;
  std::vector<PendingSection> sections_;
};

}  // namespace mbk
