// Reading the example at a continuous point for the point query ([Wang20] Sec. 4.2): bilinear interpolation of
// two channels between texel centres, CLIPPED at the border (glint_technique.h: the example is not tileable),
// with its exact 2x2 derivative. The channels are the normal components n_x, n_y, or, for histogram-preserving
// blending, their standardized values G(n_x), G(n_y) ([Heitz18] Sec. 3: the example is standardized texel by
// texel, and the Gaussian example is what is interpolated; blended_normal.h).
//
// Point e = (e_0, e_1) in texel units along (x, row); texel (x, row) has its centre at (x + 0.5, row + 0.5).
// With t = e - 0.5, x0 = floor(t_0), f = t_0 - x0 (likewise along rows), the four texels x0, x0 + 1 (rows
// likewise) are read with indices clamped to [0, W - 1] x [0, H - 1]:
//     n(e) = (1 - f_0)(1 - f_1) n00 + f_0 (1 - f_1) n10 + (1 - f_0) f_1 n01 + f_0 f_1 n11,
// and J = dn/de is the exact derivative of that interpolant (rows: n_x, n_y; columns: d/de_0, d/de_1). Within
// half a texel of the border the clamped texels coincide, so n is constant across the border and J's column is
// 0 there. Kinks (measure zero): on lines through texel centres (t integer) J jumps; there the cell on the +e
// side (floor) gives the one-sided derivative.
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/image/normal_map.h"

namespace mbk {

// Two channels per texel, row-major like NormalMap (texel (x, row) at index row * width + x).
struct ExampleChannels {
  uint32_t width = 0, height = 0;
  std::vector<Vec2> texels;
};

// The example's normal components (n_x, n_y) as doubles.
ExampleChannels normal_components(const NormalMap& example);

struct NormalSample {
  Vec2 n;         // (n_x, n_y)
  Mat2 jacobian;  // d n / d (position), rows n_x, n_y
};

// Requires a non-empty example and a finite e (any e: indices clamp).
NormalSample sample_example_bilinear(const ExampleChannels& example, const Vec2& e);

}  // namespace mbk
