// Chunks of a texel's normals on an octahedral grid (see vmf_normal_chunks.h).
#include "libbake/filter/vmf_normal_chunks.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <tuple>

#include "formats/error.h"

namespace mbk {
namespace {

constexpr uint32_t kGrid = uint32_t(1) << kVmfChunkGridBits;

// The cell of n on the finest grid: octahedral coordinates in [-1, 1]^2, scaled to [0, kGrid).
uint32_t cell_coordinate(double c) { return std::min(kGrid - 1, uint32_t(std::max(0.0, (c + 1.0) * 0.5 * kGrid))); }

// Interleaves the bits of x (even positions) and y (odd positions).
uint64_t morton(uint32_t x, uint32_t y) {
  uint64_t code = 0;
  for (int b = 0; b < kVmfChunkGridBits; ++b)
    code |= (uint64_t((x >> b) & 1u) << (2 * b)) | (uint64_t((y >> b) & 1u) << (2 * b + 1));
  return code;
}

uint64_t cell_code(const Vec3& n) {
  const double l1 = std::abs(n.x()) + std::abs(n.y()) + std::abs(n.z());
  double u = n.x() / l1, v = n.y() / l1;
  if (n.z() < 0.0) {
    const double fu = (1.0 - std::abs(v)) * (u < 0.0 ? -1.0 : 1.0), fv = (1.0 - std::abs(u)) * (v < 0.0 ? -1.0 : 1.0);
    u = fu, v = fv;
  }
  return morton(cell_coordinate(u), cell_coordinate(v));
}

}  // namespace

std::vector<WeightedNormal> vmf_normal_chunks(std::span<const WeightedNormal> normals, size_t max_chunks) {
  if (max_chunks < 1) throw Error(ExitCode::runtime_failure, "internal: vMF normal chunks with no chunk allowed");
  // Normals sorted by the Morton code of their cell, then by value, then by position: identical normals are
  // neighbours in their given order, as a stable sort leaves them, without its buffer of up to the whole order (at
  // the top level that buffer set the bake's peak memory).
  struct Entry {
    uint64_t code;
    const WeightedNormal* normal;
  };
  std::vector<Entry> order(normals.size());
  for (size_t i = 0; i < normals.size(); ++i) order[i] = {cell_code(normals[i].n), &normals[i]};
  const auto key = [](const Entry& e) {
    return std::tuple(e.code, e.normal->n.x(), e.normal->n.y(), e.normal->n.z(), e.normal);
  };
  std::sort(order.begin(), order.end(), [&](const Entry& a, const Entry& b) { return key(a) < key(b); });
  const auto same_normal = [](const Entry& a, const Entry& b) { return a.normal->n == b.normal->n; };
  // Atoms: the runs of identical normals. cells[k]: occupied cells of the 2^k grid. Neighbours in the order whose
  // codes first differ in bit pair p (bits 2p and 2p + 1, counted from the lowest) lie in different cells of the
  // grids k >= kVmfChunkGridBits - p.
  size_t atoms = normals.empty() ? 0 : 1;
  std::vector<size_t> cells(kVmfChunkGridBits + 1, atoms);
  for (size_t i = 1; i < order.size(); ++i) {
    atoms += !same_normal(order[i], order[i - 1]);
    const uint64_t differ = order[i].code ^ order[i - 1].code;
    if (differ == 0) continue;
    const int pair = (std::bit_width(differ) - 1) / 2;
    for (int k = kVmfChunkGridBits - pair; k <= kVmfChunkGridBits; ++k) ++cells[size_t(k)];
  }
  // Exact when the atoms fit; else the finest grid that fits, where an atom of weight >= 1 / max_chunks (at most
  // max_chunks of them) stays a chunk of its own.
  const bool exact = atoms <= max_chunks;
  int k = kVmfChunkGridBits;
  while (k > 0 && cells[size_t(k)] > max_chunks) --k;
  const int shift = 2 * (kVmfChunkGridBits - k);
  const double heavy = 1.0 / double(max_chunks);
  std::vector<WeightedNormal> chunks;
  Vec3 sum = Vec3::Zero();
  double weight = 0.0;
  const auto emit = [&](Vec3& s, double& w) {
    if (w > 0.0) chunks.push_back({s / w, w});
    s = Vec3::Zero(), w = 0.0;
  };
  for (size_t i = 0, end; i < order.size(); i = end) {
    // The atom [i, end).
    double atom_weight = 0.0;
    for (end = i; end < order.size() && same_normal(order[end], order[i]); ++end) atom_weight += order[end].normal->w;
    if (exact || atom_weight >= heavy) {
      chunks.push_back({order[i].normal->n, atom_weight});
    } else {
      sum += atom_weight * order[i].normal->n, weight += atom_weight;
    }
    if (!exact && (end == order.size() || (order[end].code >> shift) != (order[i].code >> shift))) emit(sum, weight);
  }
  return chunks;
}

}  // namespace mbk
