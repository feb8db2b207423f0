// Test fixtures for the container: a small valid `mip` asset built by hand (its levels computed by brute
// force over the area each texel covers, independently of the baker), and readable helpers that corrupt one field of a
// valid file and, where a test wants a deeper check to fire, reseal the checksums around it (reseal.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

#include "formats/asset_writer.h"
#include "formats/byte_io.h"
#include "formats/container_layout.h"
#include "formats/mip_levels.h"
#include "tests/formats/reseal.h"

namespace mbk::test {

// A W x H normal field with varied directions, as level 0 of a mip asset.
inline std::vector<float> unit_normals(uint32_t w, uint32_t h) {
  std::vector<float> n(size_t(w) * h * 3);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      double a = 0.3 * std::sin(1.7 * x + 0.4 * y), b = 0.25 * std::cos(0.9 * y - 1.3 * x);
      double len = std::sqrt(a * a + b * b + 1.0);
      float* p = &n[(size_t(y) * w + x) * 3];
      p[0] = float(a / len), p[1] = float(b / len), p[2] = float(1.0 / len);
      float l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for (int c = 0; c < 3; ++c) p[c] /= l;
    }
  return n;
}

// Length of the overlap of [a, b) and [c, d).
inline double overlap_length(double a, double b, double c, double d) {
  return std::max(0.0, std::min(b, d) - std::max(a, c));
}

// Level k texel (i, j) = area-weighted mean (per channel; 3 for normals) of the finest texels over its rectangle
// [i W / w_k, (i+1) W / w_k) x [j H / h_k, (j+1) H / h_k), by brute force: every finest texel, weighted by the
// area of its square's overlap with the rectangle.
inline std::vector<std::vector<float>> brute_force_pyramid(const std::vector<float>& level0, uint32_t w, uint32_t h,
                                                           uint32_t channels = 3) {
  std::vector<std::vector<float>> levels;
  auto sizes = mip_level_sizes(w, h);
  for (size_t k = 0; k < sizes.size(); ++k) {
    const uint32_t lw = sizes[k].width, lh = sizes[k].height;
    const double tx = double(w) / lw, ty = double(h) / lh;  // texel size in finest texels
    std::vector<float> L(size_t(lw) * lh * channels);
    for (uint32_t j = 0; j < lh; ++j)
      for (uint32_t i = 0; i < lw; ++i) {
        std::vector<double> s(channels, 0.0);
        double area = 0;
        for (uint32_t y = 0; y < h; ++y)
          for (uint32_t x = 0; x < w; ++x) {
            const double a =
                overlap_length(i * tx, (i + 1) * tx, x, x + 1.0) * overlap_length(j * ty, (j + 1) * ty, y, y + 1.0);
            area += a;
            for (uint32_t c = 0; c < channels; ++c) s[c] += a * level0[(size_t(y) * w + x) * channels + c];
          }
        for (uint32_t c = 0; c < channels; ++c) L[(size_t(j) * lw + i) * channels + c] = float(s[c] / area);
      }
    levels.push_back(std::move(L));
  }
  return levels;
}

inline nlohmann::json mip_metadata(uint32_t w, uint32_t h, size_t levels) {
  return {{"inputs", nlohmann::json::array()},
          {"parameters", {{"width", w}, {"height", h}, {"levels", levels}}},
          {"conventions", {{"normal_convention", "+Y"}}},
          {"statistics", nlohmann::json::object()}};
}

// The W x H fixture; for corrupt variants, without its last `dropped` levels and with parameters[key] = value
// when a key is given (written, not patched, so the metadata may grow).
inline AssetWriter mip_writer(uint32_t w, uint32_t h, size_t dropped = 0, const std::string& key = "",
                              const nlohmann::json& value = nullptr) {
  auto levels = brute_force_pyramid(unit_normals(w, h), w, h);
  auto sizes = mip_level_sizes(w, h);
  nlohmann::json metadata = mip_metadata(w, h, levels.size());
  if (!key.empty()) metadata["parameters"][key] = value;
  AssetWriter writer("mip", metadata);
  for (size_t k = 0; k + dropped < levels.size(); ++k)
    writer.add<float>("level_" + std::to_string(k), {sizes[k].height, sizes[k].width, 3}, levels[k]);
  return writer;
}

inline std::vector<uint8_t> valid_mip_bytes(uint32_t w = 5, uint32_t h = 3) { return mip_writer(w, h).serialize(); }

// --- corruption helpers -------------------------------------------------------------------------------
inline uint64_t section_table_offset(const std::vector<uint8_t>& f) {
  return load_le<uint64_t>(&f[header_field::section_table_offset]);
}
inline uint64_t entry_offset(const std::vector<uint8_t>& f, size_t i) {
  return section_table_offset(f) + i * kSectionEntrySize;
}
inline uint64_t section_data_offset(const std::vector<uint8_t>& f, size_t i) {
  return load_le<uint64_t>(&f[entry_offset(f, i) + entry_field::offset]);
}

// Recomputes section i's checksum after its data changed, then the header's.
inline void reseal_section(std::vector<uint8_t>& f, size_t i) {
  uint64_t e = entry_offset(f, i);
  uint64_t off = load_le<uint64_t>(&f[e + entry_field::offset]),
           len = load_le<uint64_t>(&f[e + entry_field::byte_length]);
  store_le<uint64_t>(&f[e + entry_field::checksum], checksum_of(&f[off], len));
  reseal_header(f);
}

// Replaces the metadata JSON (same length required by the layout: pads with spaces), resealing.
inline void replace_metadata(std::vector<uint8_t>& f, const std::string& json) {
  uint64_t meta_off = load_le<uint64_t>(&f[header_field::metadata_offset]);
  uint64_t meta_size = load_le<uint64_t>(&f[header_field::metadata_size]);
  std::string text = json;
  if (text.size() > meta_size) throw std::runtime_error("replacement metadata too long");
  text.resize(meta_size, ' ');
  std::memcpy(&f[meta_off], text.data(), text.size());
  reseal_header(f);
}

// `f` with element `index` of f32 section `section` set to `value`, resealed.
inline std::vector<uint8_t> with_f32_element(std::vector<uint8_t> f, size_t section, size_t index, float value) {
  store_le<float>(&f[section_data_offset(f, section) + 4 * index], value);
  reseal_section(f, section);
  return f;
}

// `f` with `edit` applied to its metadata "parameters" (no longer than before), resealed.
inline std::vector<uint8_t> with_parameters_edited(std::vector<uint8_t> f,
                                                   const std::function<void(nlohmann::json&)>& edit) {
  const uint64_t meta_off = load_le<uint64_t>(&f[header_field::metadata_offset]);
  const uint64_t meta_size = load_le<uint64_t>(&f[header_field::metadata_size]);
  nlohmann::json m = nlohmann::json::parse(std::string(f.begin() + meta_off, f.begin() + meta_off + meta_size));
  edit(m["parameters"]);
  replace_metadata(f, m.dump());
  return f;
}

// `f` with metadata parameters[key] replaced (no longer than before), resealed.
inline std::vector<uint8_t> with_parameter(std::vector<uint8_t> f, const std::string& key,
                                           const nlohmann::json& value) {
  return with_parameters_edited(std::move(f), [&](nlohmann::json& p) { p[key] = value; });
}

// `f` without metadata parameters[key], resealed.
inline std::vector<uint8_t> without_parameter(std::vector<uint8_t> f, const std::string& key) {
  return with_parameters_edited(std::move(f), [&](nlohmann::json& p) { p.erase(key); });
}

inline float get_f32(const std::vector<uint8_t>& f, uint64_t off) { return load_le<float>(&f[off]); }
inline void set_f32(std::vector<uint8_t>& f, uint64_t off, float v) { store_le<float>(&f[off], v); }

}  // namespace mbk::test
