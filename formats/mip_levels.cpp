// MIP level sizes and per-texel coverage weights (see mip_levels.h).
//
// Positions are kept exact in integers: measured in units of 1 / level_extent finest texels, texel i spans
// [i extent, (i+1) extent) and finest texel x spans [x level_extent, (x+1) level_extent). An overlap is an
// integer, and its weight overlap / extent is one correctly rounded double division.
#include "formats/mip_levels.h"

#include <algorithm>
#include <limits>

#include <nlohmann/json.hpp>

#include "formats/error.h"

namespace mbk {

std::vector<LevelSize> mip_level_sizes(uint32_t width, uint32_t height) {
  std::vector<LevelSize> levels;
  if (width == 0 || height == 0) return levels;
  for (uint32_t k = 0;; ++k) {
    const LevelSize s{std::max(1u, width >> k), std::max(1u, height >> k)};
    levels.push_back(s);
    if (s.width == 1 && s.height == 1) return levels;
  }
}

std::vector<std::vector<MipWeight>> mip_texel_weights(uint32_t level_extent, uint32_t extent) {
  if (level_extent == 0 || level_extent > extent)
    throw Error(ExitCode::runtime_failure, "internal: MIP level of " + std::to_string(level_extent) +
                                               " texels over an axis of " + std::to_string(extent));
  const uint64_t n = level_extent, e = extent;
  std::vector<std::vector<MipWeight>> texels(level_extent);
  for (uint64_t i = 0; i < n; ++i) {
    const uint64_t begin = i * e, end = (i + 1) * e;
    for (uint64_t x = begin / n; x * n < end; ++x) {
      const uint64_t overlap = std::min(end, (x + 1) * n) - std::max(begin, x * n);
      texels[i].push_back({uint32_t(x), double(overlap) / double(e)});
    }
  }
  return texels;
}

namespace {

// parameters[key] as an integer in [lo, hi], or what is wrong with it (see parse_mip_parameters).
std::string read_count(const nlohmann::json& parameters, const char* key, uint64_t lo, uint64_t hi, uint64_t& value) {
  const std::string name = std::string("parameters.") + key;
  const auto it = parameters.find(key);
  if (it == parameters.end()) return name + " is missing";
  // Parsed non-negative integers are unsigned and keep all 64 bits (no wrap); floats are never counts.
  const bool whole = it->is_number_unsigned() || (it->is_number_integer() && it->get<int64_t>() >= 0);
  if (!whole || it->get<uint64_t>() < lo || it->get<uint64_t>() > hi)
    return name + " is " + it->dump() + ", not an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
  value = it->get<uint64_t>();
  return {};
}

}  // namespace

std::string parse_mip_parameters(const nlohmann::json& parameters, std::vector<LevelSize>& sizes) {
  if (!parameters.is_object()) return "parameters is " + parameters.dump() + ", not an object";
  constexpr uint64_t kMaxSide = std::numeric_limits<uint32_t>::max();
  uint64_t width = 0, height = 0, levels = 0;
  for (const auto& [key, value] : {std::pair{"width", &width}, std::pair{"height", &height}})
    if (std::string problem = read_count(parameters, key, 1, kMaxSide, *value); !problem.empty()) return problem;
  std::vector<LevelSize> expected = mip_level_sizes(uint32_t(width), uint32_t(height));
  if (std::string problem = read_count(parameters, "levels", 1, kMaxSide, levels); !problem.empty()) return problem;
  if (levels != expected.size())
    return "parameters.levels is " + std::to_string(levels) + ", but a " + std::to_string(width) + "x" +
           std::to_string(height) + " pyramid has " + std::to_string(expected.size()) + " levels";
  sizes = std::move(expected);
  return {};
}

bool is_level_section_name(const std::string& name) {
  if (name.rfind("level_", 0) != 0 || name.size() == 6) return false;
  return name.find_first_not_of("0123456789", 6) == std::string::npos;
}

}  // namespace mbk
