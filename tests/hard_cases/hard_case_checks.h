// Independent references shared by the hard-case suite (tests/hard_cases/): maps filled from a function, the
// real SH basis from the C++17 special function std::sph_legendre (not libbake/core/sh_basis.h), and the
// area-weighted mean over the finest normals a MIP texel covers (formats/mip_levels.h weights).
#pragma once

#include <cmath>
#include <functional>
#include <numbers>

#include "formats/mip_levels.h"
#include "libbake/image/normal_map.h"

namespace mbk::test {

inline NormalMap filled(uint32_t w, uint32_t h, const std::function<Vec3(uint32_t, uint32_t)>& normal) {
  NormalMap m;
  m.width = w, m.height = h;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) m.texels.push_back(normal(x, y).normalized().cast<float>());
  return m;
}

// Y_lm at the direction of d (any length), with sh_basis.h's conventions: std::sph_legendre(l, m, theta) carries
// the Condon-Shortley phase (-1)^m, which the basis does not, hence the sign.
inline double independent_sh(int l, int m, const Vec3& d) {
  const double theta = std::atan2(std::hypot(d.x(), d.y()), d.z()), phi = std::atan2(d.y(), d.x());
  const int am = std::abs(m);
  const double p = (am % 2 ? -1.0 : 1.0) * std::sph_legendre(unsigned(l), unsigned(am), theta);
  if (m == 0) return p;
  return std::numbers::sqrt2 * p * (m > 0 ? std::cos(am * phi) : std::sin(am * phi));
}

// sum_i w_i f(n_i) over the finest normals under texel (x, y) of the level of size (w, h).
inline void for_each_covered_normal(const NormalMap& map, uint32_t w, uint32_t h, uint32_t x, uint32_t y,
                                    const std::function<void(const Vec3&, double)>& f) {
  const auto wx = mip_texel_weights(w, map.width), wy = mip_texel_weights(h, map.height);
  for (const MipWeight& fy : wy[y])
    for (const MipWeight& fx : wx[x]) f(map.at(fx.index, fy.index).cast<double>(), fx.weight * fy.weight);
}

}  // namespace mbk::test
