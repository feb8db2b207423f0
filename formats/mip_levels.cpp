// MIP level sizes and coverage (see mip_levels.h).
#include "formats/mip_levels.h"

#include <algorithm>

namespace mbk {

std::vector<LevelSize> mip_level_sizes(uint32_t width, uint32_t height) {
  std::vector<LevelSize> levels;
  if (width == 0 || height == 0) return levels;
  LevelSize s{width, height};
  levels.push_back(s);
  while (s.width > 1 || s.height > 1) {
    s = {(s.width + 1) / 2, (s.height + 1) / 2};
    levels.push_back(s);
  }
  return levels;
}

uint32_t mip_coverage(uint32_t extent, uint32_t level, uint32_t i) {
  const uint64_t begin = uint64_t(i) << level;
  const uint64_t end = std::min<uint64_t>(uint64_t(i + 1) << level, extent);
  return end > begin ? uint32_t(end - begin) : 0;
}

}  // namespace mbk
