// MIP level sizes and per-texel coverage weights (see mip_levels.h).
//
// Positions are kept exact in integers: measured in units of 1 / level_extent finest texels, texel i spans
// [i extent, (i+1) extent) and finest texel x spans [x level_extent, (x+1) level_extent). An overlap is an
// integer, and its weight overlap / extent is one correctly rounded double division.
#include "formats/mip_levels.h"

#include <algorithm>

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

bool is_level_section_name(const std::string& name) {
  if (name.rfind("level_", 0) != 0 || name.size() == 6) return false;
  return name.find_first_not_of("0123456789", 6) == std::string::npos;
}

}  // namespace mbk
