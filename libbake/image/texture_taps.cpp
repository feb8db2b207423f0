// Bilinear taps and trilinear level blends (see texture_taps.h).
#include "libbake/image/texture_taps.h"

#include <algorithm>
#include <cmath>

namespace mbk {
namespace {

// Wraps an integer texel index into [0, n).
uint32_t wrap_index(int64_t i, int64_t n) {
  const int64_t m = i % n;
  return uint32_t(m < 0 ? m + n : m);
}

}  // namespace

Vec2 texel_coordinates(const Vec2& uv, uint32_t width, uint32_t height) {
  const double u = uv.x() - std::floor(uv.x());
  const double t = (1.0 - uv.y()) - std::floor(1.0 - uv.y());  // row coordinate as a fraction of H
  return Vec2(u * width, t * height);
}

std::array<TextureTap, 4> bilinear_taps(uint32_t width, uint32_t height, const Vec2& uv) {
  const Vec2 p = texel_coordinates(uv, width, height);
  const double fx = p.x() - 0.5, fy = p.y() - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const double ax = fx - x0, ay = fy - y0;
  const uint32_t xa = wrap_index(int64_t(x0), width), xb = wrap_index(int64_t(x0) + 1, width);
  const uint32_t ya = wrap_index(int64_t(y0), height), yb = wrap_index(int64_t(y0) + 1, height);
  return {TextureTap{xa, ya, (1 - ax) * (1 - ay)}, TextureTap{xb, ya, ax * (1 - ay)}, TextureTap{xa, yb, (1 - ax) * ay},
          TextureTap{xb, yb, ax * ay}};
}

std::vector<TextureTap> box_taps(uint32_t width, uint32_t height, const Vec2& uv, double half_x, double half_y) {
  const Vec2 c = texel_coordinates(uv, width, height);
  const double x0 = c.x() - half_x, x1 = c.x() + half_x, y0 = c.y() - half_y, y1 = c.y() + half_y;
  const double area = (x1 - x0) * (y1 - y0);
  std::vector<TextureTap> taps;
  for (double row = std::floor(y0); row < y1; row += 1.0) {
    const double cover_y = std::min(row + 1.0, y1) - std::max(row, y0);
    for (double x = std::floor(x0); x < x1; x += 1.0) {
      const double cover_x = std::min(x + 1.0, x1) - std::max(x, x0);
      taps.push_back({wrap_index(int64_t(x), width), wrap_index(int64_t(row), height), cover_x * cover_y / area});
    }
  }
  return taps;
}

LevelBlend level_blend(size_t levels, double lod) {
  const double top = double(levels - 1);
  const double l = std::clamp(lod, 0.0, top);
  const size_t fine = size_t(std::floor(l));
  const double t = l - double(fine);
  return {fine, t == 0.0 ? fine : fine + 1, t};
}

}  // namespace mbk
