// Bilinear taps and trilinear level blends (see texture_taps.h).
#include "libbake/image/texture_taps.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mbk {
namespace {

// Wraps an integer texel index into [0, n).
uint32_t wrap_index(int64_t i, int64_t n) {
  const int64_t m = i % n;
  return uint32_t(m < 0 ? m + n : m);
}

// The overlaps (in texels) of [lo, hi) with the texels of a wrapping axis of n texels, folded modulo n: one entry
// per texel met.
std::vector<std::pair<uint32_t, double>> axis_overlaps(double lo, double hi, uint32_t n) {
  std::vector<std::pair<uint32_t, double>> overlaps;
  if (std::ceil(hi - lo) + 1.0 < double(n)) {  // fewer texels than the axis: none is met twice
    for (double t = std::floor(lo); t < hi; t += 1.0)
      overlaps.emplace_back(wrap_index(int64_t(t), n), std::min(t + 1.0, hi) - std::max(t, lo));
    return overlaps;
  }
  // The box covers the axis `full` times and then a rest shorter than it.
  const double full = std::floor((hi - lo) / n);
  std::vector<double> cover(n, full);
  const double rest = lo + full * n;
  for (double t = std::floor(rest); t < hi; t += 1.0)
    cover[wrap_index(int64_t(t), n)] += std::min(t + 1.0, hi) - std::max(t, rest);
  for (uint32_t i = 0; i < n; ++i)
    if (cover[i] > 0.0) overlaps.emplace_back(i, cover[i]);
  return overlaps;
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
  if (!(half_x > 0.0) || !(half_y > 0.0) || !std::isfinite(half_x) || !std::isfinite(half_y)) return {};
  const Vec2 c = texel_coordinates(uv, width, height);
  const double x0 = c.x() - half_x, x1 = c.x() + half_x, y0 = c.y() - half_y, y1 = c.y() + half_y;
  const double area = (x1 - x0) * (y1 - y0);
  const auto xs = axis_overlaps(x0, x1, width);
  const auto ys = axis_overlaps(y0, y1, height);
  std::vector<TextureTap> taps;
  taps.reserve(xs.size() * ys.size());
  for (const auto& [row, cover_y] : ys)
    for (const auto& [x, cover_x] : xs) taps.push_back({x, row, cover_x * cover_y / area});
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
