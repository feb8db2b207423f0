// Procedural normal maps standing in for the materials of the papers (microbake gen KIND): the registry of
// generator kinds. Every generator is deterministic (integer hashes only, per-texel results), tiles, works
// for any size from 1 x 1 up (non-square, non-power-of-two), and draws the same picture at every
// resolution: feature counts are set per longest side and scaled to the other side, so features stay
// round on non-square maps. Maps derived from a height field are integrable (height_field.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "libbake/core/progress.h"
#include "libbake/image/normal_map.h"

namespace mbk {

struct MapSize {
  uint32_t width = 512, height = 512;
  uint32_t longest() const { return width > height ? width : height; }
  // How many features fit along `side` (width or height) given `per_longest` along the longest side; >= 1.
  uint32_t features_along(uint32_t side, double per_longest) const {
    const double n = std::floor(per_longest * side / longest() + 0.5);
    return n < 1.0 ? 1u : uint32_t(n);
  }
};

struct GeneratorKind {
  std::string_view name;
  std::string_view summary;
  bool from_height;  // slopes are central differences of a periodic height field (integrable)
  NormalMap (*generate)(const MapSize& size, uint32_t seed, Progress& progress);
};

std::span<const GeneratorKind> generator_kinds();
const GeneratorKind* find_generator(std::string_view name);
// "bumps, brushed, ..." for help texts and error messages.
std::string generator_names();

// Runs a generator with its progress task started; Error(bad_command_line) for an unknown kind or a size
// outside 1..kMaxNormalMapSide.
NormalMap generate_normal_map(std::string_view kind, const MapSize& size, uint32_t seed, Progress& progress);

// The generators, one file each (libbake/gen/<name>.cpp).
NormalMap generate_bumps(const MapSize& size, uint32_t seed, Progress& progress);
NormalMap generate_brushed(const MapSize& size, uint32_t seed, Progress& progress);
NormalMap generate_scratches(const MapSize& size, uint32_t seed, Progress& progress);
NormalMap generate_flakes(const MapSize& size, uint32_t seed, Progress& progress);
NormalMap generate_leather(const MapSize& size, uint32_t seed, Progress& progress);
NormalMap generate_panels(const MapSize& size, uint32_t seed, Progress& progress);

}  // namespace mbk
