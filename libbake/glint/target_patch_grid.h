// The target grid of the point query ([Wang20] Sec. 4.2, Fig. 3): which four example patches are blended at a
// point u of the infinite target plane, where in the example each one is read, and with which weights.
//
// Coordinates: u = (u_0, u_1) in EXAMPLE-TEXEL units along the example's own axes (u_0 along the column index
// x, u_1 along the row index, i.e. DOWN the image, like example_bilinear.h); the evaluator maps tangent +v to
// -u_1. With P the example patch side (texels) and h = P / 2 the target patch side:
// - Target patch (i, j) = [i h, (i + 1) h) x [j h, (j + 1) h), i = floor(u_0 / h), j = floor(u_1 / h); its local
//   coordinates are f = u / h - (i, j) in [0, 1)^2.
// - Grid vertex (a, b) owns one example patch of side P, centred on the vertex: it covers the target square
//   [(a - 1) h, (a + 1) h] x [(b - 1) h, (b + 1) h], so neighbouring patches overlap by half, and every target
//   patch lies in the four patches of its corners (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1).
// - The patch of vertex (a, b) starts at the integer example texel origin(a, b) = (hash4(seed, a, b, 0) mod
//   (W - P + 1), hash4(seed, a, b, 1) mod (H - P + 1)) (libbake/core/hash.h; a, b are taken modulo 2^32, two's
//   complement, so negative indices hash like any other). The patch [origin, origin + P]^2 lies inside the
//   example [0, W] x [0, H]. The modulo bias is below (W - P + 1) / 2^32: negligible.
// - Point u reads the patch of vertex (a, b) at example point e = origin(a, b) + u - ((a - 1) h, (b - 1) h),
//   which is in [origin, origin + P]^2 for the four corners of u's target patch; de/du is the identity.
// - Weights: the bilinear (tent) weights of the four corners, w = (1 - f_0)(1 - f_1), f_0 (1 - f_1),
//   (1 - f_0) f_1, f_0 f_1; they sum to 1, and dw/du = (dw/df) / h.
// Seams (measure zero): on target patch borders (f_0 or f_1 = 0) the corner set changes; the weights of the
// corners that leave are 0 there, so a linear blend is continuous but its derivative jumps. The point is
// assigned to the patch on its +u side (floor), and derivatives there are that patch's one-sided ones.
#pragma once

#include <array>
#include <cstdint>

#include "libbake/core/eigen.h"

namespace mbk {

struct TargetPatchCorner {
  int64_t a = 0, b = 0;  // grid vertex
  Vec2 example_point;    // e, where u reads this corner's example patch (texel units, [0, W] x [0, H])
  double weight = 0.0;   // bilinear weight at u
  Vec2 weight_gradient;  // d weight / du
};

struct TargetPatchLocation {
  int64_t i = 0, j = 0;  // target patch index
  Vec2 local;            // f in [0, 1)^2
  // Corners in the order (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1).
  std::array<TargetPatchCorner, 4> corners;
};

class TargetPatchGrid {
 public:
  // Throws Error(bad_command_line) unless 2 <= patch_side <= min(example_width, example_height).
  TargetPatchGrid(uint32_t example_width, uint32_t example_height, uint32_t patch_side, uint32_t seed);

  uint32_t patch_side() const { return patch_side_; }
  double target_side() const { return 0.5 * patch_side_; }
  // The example texel where the patch of grid vertex (a, b) starts (see above).
  std::array<uint32_t, 2> patch_origin(int64_t a, int64_t b) const;
  // Throws Error(invalid_input) when u is not finite or so far out that a patch index leaves int64.
  TargetPatchLocation locate(const Vec2& u) const;

 private:
  uint32_t width_, height_, patch_side_, seed_;
};

}  // namespace mbk
