// The target grid of the point query ([Wang20] Sec. 4.2): see target_patch_grid.h.
#include "libbake/glint/target_patch_grid.h"

#include <cmath>
#include <string>

#include "formats/error.h"
#include "libbake/core/hash.h"

namespace mbk {

TargetPatchGrid::TargetPatchGrid(uint32_t example_width, uint32_t example_height, uint32_t patch_side, uint32_t seed)
    : width_(example_width), height_(example_height), patch_side_(patch_side), seed_(seed) {
  if (patch_side < 2 || patch_side > example_width || patch_side > example_height)
    throw Error(ExitCode::bad_command_line,
                "glint patch side " + std::to_string(patch_side) + " must be in [2, min(width, height)] for a " +
                    std::to_string(example_width) + "x" + std::to_string(example_height) + " example",
                "point query");
}

std::array<uint32_t, 2> TargetPatchGrid::patch_origin(int64_t a, int64_t b) const {
  // The P-NDF asks for the same four vertices many times in a row (a texel's sub-elements and bounds all lie in
  // one target patch), so each thread keeps the last origin of each vertex parity class (a mod 2, b mod 2): the
  // four corners of a patch never evict each other.
  // A memo only: the key is everything the origin is a function of (not the object, whose address a later
  // grid may reuse).
  struct Memo {
    std::array<uint32_t, 4> grid{};  // width, height, patch side, seed
    int64_t a = 0, b = 0;
    bool valid = false;
    std::array<uint32_t, 2> origin{};
  };
  thread_local std::array<Memo, 4> memo;
  const std::array<uint32_t, 4> grid{width_, height_, patch_side_, seed_};
  Memo& m = memo[size_t((a & 1) | ((b & 1) << 1))];
  if (m.valid && m.a == a && m.b == b && m.grid == grid) return m.origin;
  const auto ua = uint32_t(uint64_t(a)), ub = uint32_t(uint64_t(b));  // modulo 2^32
  const uint32_t vertex = hash3(seed_, ua, ub);                       // hash4(seed, a, b, axis), shared part
  m = {grid,
       a,
       b,
       true,
       {hash_combine(vertex, 0u) % (width_ - patch_side_ + 1), hash_combine(vertex, 1u) % (height_ - patch_side_ + 1)}};
  return m.origin;
}

TargetPatchLocation TargetPatchGrid::locate(const Vec2& u) const {
  const double h = target_side();
  const double s0 = std::floor(u.x() / h), s1 = std::floor(u.y() / h);
  constexpr double kLimit = 9.0e18;  // below 2^63, so the patch indices and their + 1 fit in int64
  if (!(std::abs(s0) < kLimit && std::abs(s1) < kLimit))
    throw Error(ExitCode::invalid_input, "point query position is not finite or out of range", "point query");
  TargetPatchLocation loc;
  loc.i = int64_t(s0);
  loc.j = int64_t(s1);
  loc.local = Vec2(u.x() / h - s0, u.y() / h - s1);
  const double f0 = loc.local.x(), f1 = loc.local.y();
  for (int k = 0; k < 4; ++k) {
    const int dx = k & 1, dy = k >> 1;
    TargetPatchCorner& c = loc.corners[k];
    c.a = loc.i + dx;
    c.b = loc.j + dy;
    const std::array<uint32_t, 2> origin = patch_origin(c.a, c.b);
    // e = origin + u - (a - 1) h, written with the local coordinate so that it stays exact far from 0.
    c.example_point = Vec2(origin[0] + (f0 + 1 - dx) * h, origin[1] + (f1 + 1 - dy) * h);
    const double wx = dx ? f0 : 1.0 - f0, wy = dy ? f1 : 1.0 - f1;
    const double dwx = dx ? 1.0 : -1.0, dwy = dy ? 1.0 : -1.0;  // d wx / d f0, d wy / d f1
    c.weight = wx * wy;
    c.weight_gradient = Vec2(dwx * wy, wx * dwy) / h;
  }
  return loc;
}

}  // namespace mbk
