// Chunks of a texel's normals for the coarse-level vMF fits (libbake/filter/vmf_pyramid.h): chunked EM
// (Verbeek, Nunnink and Vlassis 2006, "Accelerated EM-based clustering of large data sets") with the normals of
// one chunk sharing their responsibilities. For the vMF this is exact bookkeeping, not an approximation of the
// E-step's terms: log(alpha_j g_j(n)) = log(alpha_j C(kappa_j)) + kappa_j mu_j . n is linear in n, so the sum
// over a chunk b of w_i log(alpha_j g_j(n_i)) is W_b log(alpha_j C(kappa_j)) + kappa_j mu_j . S_b with
// W_b = sum w_i and S_b = sum w_i n_i. EM with shared responsibilities is plain EM on the points m_b = S_b / W_b
// (|m_b| <= 1) of weight W_b (fit_vmf_mixture accepts them as they are), and its log-likelihood is a lower bound
// of that of the normals, tight when the responsibilities are constant over every chunk.
//
// The chunks are cells of the octahedral map of the sphere (n / |n|_1, the lower hemisphere folded outwards) on
// a 2^k x 2^k grid, k <= kVmfChunkGridBits: the finest grid whose occupied cells number at most max_chunks.
// Normals are sorted once by the Morton code of their cell at the finest grid, so the cells of every coarser
// grid are runs of that order and one pass counts them for every k.
#pragma once

#include <span>
#include <vector>

#include "libbake/filter/vmf_mixture.h"

namespace mbk {

// Bits per axis of the finest chunk grid (a cell is ~0.04 degrees across near the poles of the octahedron).
inline constexpr int kVmfChunkGridBits = 12;

// The chunks (m_b, W_b) of the finest grid with at most max_chunks occupied cells, in Morton order of their
// cells. Error(runtime_failure) for max_chunks < 1.
std::vector<WeightedNormal> vmf_normal_chunks(std::span<const WeightedNormal> normals, size_t max_chunks);

}  // namespace mbk
