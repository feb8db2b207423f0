// The MIP level rule shared by every pyramid microbake bakes (normal MIP pyramids here; SH and vMF
// pyramids later). Level 0 is the full image; level k has ceil(W / 2^k) x ceil(H / 2^k) texels, down to
// 1 x 1. Texel (i, j) of level k covers the finest texels [i 2^k, (i+1) 2^k) x [j 2^k, (j+1) 2^k) clipped to
// the image, and holds the mean over exactly those: odd sizes need no special case and no texel is counted
// twice. Computed from level k-1, a parent is the mean of its 1, 2 or 4 children weighted by the number of
// finest texels each covers.
#pragma once

#include <cstdint>
#include <vector>

namespace mbk {

struct LevelSize {
  uint32_t width, height;
};

std::vector<LevelSize> mip_level_sizes(uint32_t width, uint32_t height);

// Number of finest texels that texel i of level k covers along an axis of `extent` finest texels.
uint32_t mip_coverage(uint32_t extent, uint32_t level, uint32_t i);

}  // namespace mbk
