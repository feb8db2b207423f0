// Tileable gradient noise and its fractal sum (see periodic_noise.h).
#include "libbake/gen/periodic_noise.h"

#include <cmath>

#include "libbake/core/hash.h"

namespace mbk {
namespace {

uint32_t wrap(int64_t i, uint32_t period) {
  const int64_t m = i % int64_t(period);
  return uint32_t(m < 0 ? m + period : m);
}

// [Perlin02] fade: 6t^5 - 15t^4 + 10t^3, zero first and second derivatives at 0 and 1.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// One of eight fixed gradients (axes and diagonals), dotted with the offset (dx, dy).
double gradient_dot(uint32_t h, double dx, double dy) {
  switch (h & 7u) {
    case 0:
      return dx + dy;
    case 1:
      return -dx + dy;
    case 2:
      return dx - dy;
    case 3:
      return -dx - dy;
    case 4:
      return dx;
    case 5:
      return -dx;
    case 6:
      return dy;
    default:
      return -dy;
  }
}

}  // namespace

double periodic_gradient_noise(double x, double y, uint32_t period_x, uint32_t period_y, uint32_t seed) {
  const double fx0 = std::floor(x), fy0 = std::floor(y);
  const double dx = x - fx0, dy = y - fy0;
  const uint32_t x0 = wrap(int64_t(fx0), period_x), x1 = wrap(int64_t(fx0) + 1, period_x);
  const uint32_t y0 = wrap(int64_t(fy0), period_y), y1 = wrap(int64_t(fy0) + 1, period_y);
  const double n00 = gradient_dot(hash3(seed, x0, y0), dx, dy);
  const double n10 = gradient_dot(hash3(seed, x1, y0), dx - 1.0, dy);
  const double n01 = gradient_dot(hash3(seed, x0, y1), dx, dy - 1.0);
  const double n11 = gradient_dot(hash3(seed, x1, y1), dx - 1.0, dy - 1.0);
  const double sx = fade(dx), sy = fade(dy);
  return (1 - sy) * ((1 - sx) * n00 + sx * n10) + sy * ((1 - sx) * n01 + sx * n11);
}

double periodic_fbm(const Vec2& uv, uint32_t cells_x, uint32_t cells_y, int octaves, double gain, uint32_t seed) {
  double sum = 0.0, amplitude = 1.0;
  for (int o = 0; o < octaves; ++o) {
    const uint32_t px = cells_x << o, py = cells_y << o;
    sum += amplitude * periodic_gradient_noise(uv.x() * px, uv.y() * py, px, py, hash_combine(seed, uint32_t(o)));
    amplitude *= gain;
  }
  return sum;
}

int octaves_resolved(uint32_t cells, uint32_t texels, int wanted) {
  int n = 1;
  while (n < wanted && (uint64_t(cells) << n) * 2 <= texels) ++n;
  return n;
}

}  // namespace mbk
