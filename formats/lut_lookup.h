// Looking up a standardization table: THE lookup convention of asset kind `lut` (formats/lut_layout.h), as plain
// functions over plain arrays. This is what the evaluator calls (histogram-preserving blending, [Wang20] Eq. 6, and
// its Jacobian, [Wang20] appendix): it depends on nothing but the arrays, never on the baker, so a shader port
// needs these few lines and the asset's sections.
//
// A table over [lo, hi] of size >= 2 samples v_0 .. v_{size-1} at s_j = lo + j (hi - lo) / (size - 1), and its
// size - 1 slopes d_j (the exact derivatives of the piecewise-linear interpolant). For x in [lo, hi]:
//
//     t = (x - lo) / (hi - lo) * (size - 1),   i = min(floor(t), size - 2),   f = t - i,
//     value = v_i + f (v_{i+1} - v_i),          derivative = d_i,
//
// so on [s_i, s_{i+1}) the derivative is that interval's slope, and at hi it is the last interval's. Outside
// [lo, hi] the table is clamped: value v_0 below lo (and for NaN), v_{size-1} above hi, derivative 0 (the
// clamped function is flat there). When lo == hi the table is constant and the derivative 0. As a GPU 1-D
// texture with linear filtering and clamp-to-edge, the texture coordinate is (0.5 + t) / size.
#pragma once

#include <span>

namespace mbk {

struct LutTableView {
  double lo = 0.0, hi = 0.0;
  std::span<const float> values;  // size >= 2 samples
  std::span<const float> slopes;  // size - 1 slopes
};

struct LutSample {
  double value = 0.0;
  double derivative = 0.0;
};

// The interpolated value and its derivative d value / dx at x (every index clamped; see above).
LutSample lut_lookup(const LutTableView& table, double x);

}  // namespace mbk
