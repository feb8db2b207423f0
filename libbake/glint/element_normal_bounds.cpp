// A texel's position-normal element bounds in normal space (see element_normal_bounds.h).
#include "libbake/glint/element_normal_bounds.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "libbake/glint/glint_technique.h"

namespace mbk {
namespace {

constexpr double kReach = kGlintElementReachTexels;  // texels

}  // namespace

Vec2 element_normal_reach(const NormalMap& example, uint32_t x, uint32_t row) {
  const uint32_t x_lo = x == 0 ? 0 : x - 1, x_hi = std::min(x + 1, example.width - 1);
  const uint32_t r_lo = row == 0 ? 0 : row - 1, r_hi = std::min(row + 1, example.height - 1);
  // D^x, D^y per component (x: n_x, y: n_y), in double.
  double dx[2] = {0.0, 0.0}, dy[2] = {0.0, 0.0};
  const auto widen = [](double* d, const Vec3f& a, const Vec3f& b) {
    d[0] = std::max(d[0], std::abs(double(a.x()) - double(b.x())));
    d[1] = std::max(d[1], std::abs(double(a.y()) - double(b.y())));
  };
  for (uint32_t r = r_lo; r <= r_hi; ++r)
    for (uint32_t i = x_lo; i < x_hi; ++i) widen(dx, example.at(i + 1, r), example.at(i, r));
  for (uint32_t r = r_lo; r < r_hi; ++r)
    for (uint32_t i = x_lo; i <= x_hi; ++i) widen(dy, example.at(i, r + 1), example.at(i, r));
  return Vec2((dx[0] + dy[0]) * kReach, (dx[1] + dy[1]) * kReach);
}

void element_normal_reach_row(const NormalMap& example, uint32_t row, double* reach_x, double* reach_y) {
  const uint32_t w = example.width;
  const uint32_t r_lo = row == 0 ? 0 : row - 1, r_hi = std::min(row + 1, example.height - 1);
  // Per column i: the largest |difference| of the pairs (i, i + 1) over rows r_lo..r_hi (horizontal, i < w - 1),
  // and of the pairs (r, r + 1) for r_lo <= r < r_hi in column i (vertical), in double as the texel version.
  // Maxima of the same exact differences in any order: the same doubles as element_normal_reach.
  // Scratch per thread, kept between rows (4 doubles a column).
  thread_local std::vector<double> scratch;
  scratch.assign(4 * size_t(w), 0.0);
  double *hx = scratch.data(), *hy = hx + w, *vx = hy + w, *vy = vx + w;
  for (uint32_t r = r_lo; r <= r_hi; ++r) {
    const Vec3f* n = &example.texels[size_t(r) * w];
    for (uint32_t i = 0; i + 1 < w; ++i) {
      hx[i] = std::max(hx[i], std::abs(double(n[i + 1].x()) - double(n[i].x())));
      hy[i] = std::max(hy[i], std::abs(double(n[i + 1].y()) - double(n[i].y())));
    }
    if (r == r_hi) continue;
    const Vec3f* below = n + w;
    for (uint32_t i = 0; i < w; ++i) {
      vx[i] = std::max(vx[i], std::abs(double(below[i].x()) - double(n[i].x())));
      vy[i] = std::max(vy[i], std::abs(double(below[i].y()) - double(n[i].y())));
    }
  }
  // Texel x: horizontal pairs x - 1 and x, vertical columns x - 1 .. x + 1 (those inside the example).
  for (uint32_t x = 0; x < w; ++x) {
    double dx[2] = {0.0, 0.0}, dy[2] = {0.0, 0.0};
    const uint32_t x_lo = x == 0 ? 0 : x - 1, x_hi = std::min(x + 1, w - 1);
    for (uint32_t i = x_lo; i < x_hi; ++i) dx[0] = std::max(dx[0], hx[i]), dx[1] = std::max(dx[1], hy[i]);
    for (uint32_t i = x_lo; i <= x_hi; ++i) dy[0] = std::max(dy[0], vx[i]), dy[1] = std::max(dy[1], vy[i]);
    reach_x[x] = (dx[0] + dy[0]) * kReach;
    reach_y[x] = (dx[1] + dy[1]) * kReach;
  }
}

RmqBounds element_normal_bounds(const Vec3f& n, const Vec2& reach) {
  return {double(n.x()) - reach.x(), double(n.x()) + reach.x(), double(n.y()) - reach.y(), double(n.y()) + reach.y()};
}

RmqBounds element_normal_bounds(const NormalMap& example, uint32_t x, uint32_t row) {
  return element_normal_bounds(example.at(x, row), element_normal_reach(example, x, row));
}

}  // namespace mbk
