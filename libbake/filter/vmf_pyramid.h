// vMF mixture MIP maps: [Han07] Sec. 7.6, Alg. 7.1 per texel (libbake/filter/vmf_mixture.h), built from the
// finest level up, then made coherent from the top down (Sec. 7.6.4.2).
//
// - Level 0 has one lobe per texel: alpha = 1, r = n (|r| = 1, so kappa = kappa_max), in slot 0 before the
//   coherence pass.
// - Level k >= 1: EM over all the finest normals the texel covers (area weights, formats/mip_levels.h), from
//   two starts among the non-empty lobes of the level k-1 texels it overlaps (4J for power-of-two sizes):
//   the farthest-apart J (greedy farthest-point selection, Hochbaum-Shmoys, as the paper: first the largest
//   amplitude, then repeatedly the lobe whose smallest angular distance 1 - mu.mu_s to the chosen ones is
//   largest) and the mass-weighted farthest-apart J (largest alpha (1 - mu.mu_s), alpha summed over
//   coinciding child lobes; vmf_mixture.h, SeedRule). The fit of higher log-likelihood is kept (deviation
//   [Han07]: farthest-point seeds alone favour outlying lobes of negligible mass, the weighted ones alone
//   miss outlying facets; neither start is better on every map). Lobes coinciding with a chosen one are never
//   chosen twice, so a texel with fewer distinct directions than J starts (and stays) with fewer lobes, the
//   rest empty. Both starts run plain EM to a fixed point (one start when both rules choose the same lobes); the
//   better one then continues with the collapse guard of vmf_mixture.h (trial re-seeds of the weakest lobe).
//   A texel of more than max_chunks normals runs all of that on chunks of its normals (vmf_normal_chunks.h:
//   chunked EM, exact for the vMF's linear log density, its likelihood a lower bound), SQUAREM-accelerated like
//   every fit here, then EM continues on every finest normal: the stored
//   lobes are a fixed point of the texel's own likelihood.
// - Statistics per level: the mean log-likelihood per finest normal of the stored lobes (decoded from the
//   floats, after the coherence pass), and the EM's iterations, converged fraction and re-seeds per texel.
// - Coherence, from the top level down, texels of a level in anti-diagonal wavefronts (x + y = const, so left,
//   up and up-left neighbours are done before a texel): the neighbour target of lobe slot j is
//   t_j = sum over the parent texel (level k+1) and the left, up and up-left texels of alpha_j mu_j. Each
//   texel's lobes are first permuted to the slots that best match t (greedy on alpha_a mu_a . t_b); when
//   C > 0 (--align) the texel is then refitted with Eq. (7.26), mu_j = normalize(r_j + C t_j). The top level
//   orders its lobes by decreasing amplitude. Deviation [Han07]: the paper builds aligned lobes top-down in
//   scanline order; wavefronts use the same neighbours except up-right and let a level run in parallel
//   (by tiles of 32 x 32 texels along anti-diagonals of tiles, scanline order in a tile: the same result).
// - Storage per lobe: (alpha, alpha r), so that trilinear interpolation of the four floats is meaningful
//   (Sec. 7.6.4.2): r~ = T(alpha r) / T(alpha), kappa~ = A^-1(|r~|) (capped), mu~ = r~ / |r~|. With C > 0 the
//   stored r is |r| mu_aligned (the aligned direction with the fitted concentration).
// - Optional features (Sec. 7.6.4.1, Eq. 7.25): per lobe alpha y_j with y_j the responsibility-weighted mean of
//   the per-texel feature vectors (a colour or material image), premultiplied like r.
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/core/progress.h"
#include "libbake/filter/vmf_mixture.h"
#include "libbake/image/image_io.h"
#include "libbake/image/normal_map.h"

namespace mbk {

inline constexpr int kVmfDefaultLobes = 4;

// Chunks per texel at most for the coarse-level fits (vmf_normal_chunks.h).
inline constexpr size_t kVmfDefaultMaxChunks = 1024;

struct VmfBakeOptions {
  int lobes = kVmfDefaultLobes;
  EmOptions em;
  size_t max_chunks = kVmfDefaultMaxChunks;  // texels of more normals fit chunks first; 0: never
};

struct VmfLevelStatistics {
  double mean_iterations = 0.0, converged_fraction = 1.0;
  double mean_log_likelihood = 0.0;  // of the stored lobes, per finest normal (nats)
  double empty_lobe_fraction = 0.0;
  double mean_reseeds = 0.0;  // collapsed lobes re-seeded per texel (vmf_mixture.h, the collapse guard)
};

struct VmfLevel {
  uint32_t width = 0, height = 0;
  std::vector<float> lobes;     // [height][width][J][4]: alpha, alpha r_x, alpha r_y, alpha r_z
  std::vector<float> features;  // [height][width][J][F]: alpha y (empty without features)
  VmfLevelStatistics statistics;
};

struct VmfPyramid {
  int lobes = 0, feature_count = 0;
  std::vector<VmfLevel> levels;  // levels[0] is the finest
};

// `features` is null or an image of the map's size (any channel count, 1..4). Deterministic whatever the
// thread count. Error(invalid_input) when the feature image's size differs from the map's.
VmfPyramid build_vmf_pyramid(const NormalMap& map, const Image* features, const VmfBakeOptions& options,
                             Progress& progress);

// Decodes a stored lobe (alpha, alpha r) into a component (kappa from |r|, capped). alpha <= 0 gives an empty one.
VmfComponent decode_lobe(const float* stored, double kappa_max);

// The finest normals texel (i, j) of a w x h level covers, with their area weights (what its EM fits).
std::vector<WeightedNormal> vmf_texel_normals(const NormalMap& map, uint32_t w, uint32_t h, uint32_t i, uint32_t j);

}  // namespace mbk
