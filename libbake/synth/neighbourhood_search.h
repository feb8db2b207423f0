// Exact k-nearest neighbours of neighbourhood vectors with FLANN (kept in one .cpp: its headers compile slowly).
// Uses the exact, deterministic KDTreeSingleIndex (docs/ARCHITECTURE.md, "Determinism": FLANN's randomized trees seed
// themselves from std::random_device), so an analysis gives the same candidates on every run and thread count.
#pragma once

#include <cstdint>
#include <vector>

namespace mbk {

// points: n x dims row-major; queries: q x dims. Returns q x k indices into points, nearest first (ties by index);
// k is clamped to n.
std::vector<uint32_t> nearest_neighbours(const std::vector<float>& points, const std::vector<float>& queries,
                                         uint32_t dims, uint32_t k);

}  // namespace mbk
