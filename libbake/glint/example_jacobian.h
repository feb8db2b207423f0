// The per-texel Jacobian of an example's normal components, J = d(n_x, n_y) / d(x, row) in texel units
// (libbake/glint/glint_technique.h, shared conventions): central differences of the example, one-sided at
// the borders, because the example is not assumed tileable ([Wang20] Sec. 4.1: "not necessarily tileable").
//
//   dn/dx at (x, row) = (n(x+1) - n(x-1)) / 2        for 0 < x < W - 1
//                     = n(1) - n(0)                  at x = 0      (W > 1)
//                     = n(W-1) - n(W-2)              at x = W - 1  (W > 1)
//                     = 0                            when W = 1 (no neighbour: a constant along x)
// and likewise along the row index. Column 0 of J is d/dx (along +u); column 1 is d/d(row), i.e. DOWN the
// image: the derivative along tangent +v (up) is its negative. Row 0 of J is n_x, row 1 is n_y.
#pragma once

#include <cstdint>

#include "libbake/core/eigen.h"
#include "libbake/image/normal_map.h"

namespace mbk {

Mat2 example_jacobian(const NormalMap& example, uint32_t x, uint32_t row);

}  // namespace mbk
