// Integrability of a normal map, for tests: a map that is the normal field of a height surface has a slope
// field (p, q) = (-nx/nz, -ny/nz) = grad h, whose curl dq/dx - dp/dy vanishes. With central differences on
// the periodic grid (y up, so d/dy is (row-1) - (row+1)) the curl of a central-difference gradient is zero
// up to rounding. curl_ratio() = RMS(curl) / RMS of the two terms that must cancel: about 1e-7 for
// integrable float maps, of order 1 for unrelated fields, and larger under the wrong +Y/-Y convention
// (flipping y turns dq/dx - dp/dy into -dq/dx - dp/dy). Stencils touching a texel at the horizon
// (nz < 1e-3, slope unbounded) are left out.
#pragma once

#include <algorithm>
#include <cmath>

#include "libbake/image/normal_map.h"

namespace mbk::test {

inline double curl_ratio(const NormalMap& m) {
  const uint32_t W = m.width, H = m.height;
  auto p = [&](uint32_t x, uint32_t r) {
    const Vec3f& n = m.at(x, r);
    return -double(n.x()) / n.z();
  };
  auto q = [&](uint32_t x, uint32_t r) {
    const Vec3f& n = m.at(x, r);
    return -double(n.y()) / n.z();
  };
  double curl2 = 0.0, terms2 = 0.0;
  for (uint32_t r = 0; r < H; ++r)
    for (uint32_t x = 0; x < W; ++x) {
      const uint32_t xl = (x + W - 1) % W, xr = (x + 1) % W, up = (r + H - 1) % H, down = (r + 1) % H;
      if (std::min({m.at(xl, r).z(), m.at(xr, r).z(), m.at(x, up).z(), m.at(x, down).z()}) < 1e-3f) continue;
      const double dq_dx = 0.5 * (q(xr, r) - q(xl, r)), dp_dy = 0.5 * (p(x, up) - p(x, down));
      curl2 += (dq_dx - dp_dy) * (dq_dx - dp_dy);
      terms2 += dq_dx * dq_dx + dp_dy * dp_dy;
    }
  return terms2 > 0.0 ? std::sqrt(curl2 / terms2) : 0.0;
}

}  // namespace mbk::test
