// Gaussian stacks ([Han08] thesis Sec. 5.2.1.1, after Lefebvre & Hoppe 2005): for an m x m exemplar with m = 2^L,
// levels k = 0..L, each an m x m image. Level L is the exemplar; level k < L is the exemplar filtered with a
// periodic (toroidal: exemplars tile) Gaussian of standard deviation 2^(L-k-1) texels, i.e. the thesis' kernel of
// radius 2^(L-k) read as two standard deviations, so that level k has the detail of a 2^k x 2^k pyramid level.
// A texel of level k stands for h_k = 2^(L-k) exemplar texels (the spacing of Eq. 5.1's neighbourhoods).
// The Gaussian is folded onto the torus exactly (every tap d contributes to d mod m), so a level keeps
// exp(-2 pi^2 sigma^2 f^2 / m^2) of a cosine of f periods: level 0 (sigma = m / 2) at most exp(-pi^2 / 2) ~ 0.7%
// of any non-constant mode, nearly the mean.
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/image/image_io.h"

namespace mbk {

struct GaussianStack {
  uint32_t levels = 0;        // L + 1
  std::vector<Image> images;  // [0..L], coarsest first
  uint32_t side() const { return images.empty() ? 0 : images[0].width; }
  // h_k = 2^(L - k): exemplar texels per texel of level k.
  uint32_t spacing(uint32_t k) const { return 1u << (levels - 1 - k); }
};

// The stack of a square, power-of-two exemplar (side >= 1). Deterministic (serial sums in a fixed order).
GaussianStack build_gaussian_stack(const Image& exemplar);

// log2 of a power of two; -1 otherwise.
int exact_log2(uint32_t v);

}  // namespace mbk
