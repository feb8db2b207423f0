// Helpers of the crease tests: curve sets from segments, synthetic normal maps whose texels take a normal per
// side of a set of lines, and baking them.
#pragma once

#include <functional>
#include <vector>

#include "libbake/core/progress.h"
#include "libbake/crease/crease_asset.h"
#include "libbake/crease/curve_set.h"
#include "libbake/image/normal_map.h"

namespace mbk::test {

inline CurveSet curves_of(const std::vector<CurveSegment>& segments) {
  CurveSet s;
  for (const CurveSegment& seg : segments) s.curves.push_back({{seg.a, seg.b}, false, "test"});
  return s;
}

inline NormalMap map_from(uint32_t w, uint32_t h, const std::function<Vec3(const Vec2&)>& normal_at) {
  NormalMap m;
  m.width = w;
  m.height = h;
  for (uint32_t row = 0; row < h; ++row)
    for (uint32_t x = 0; x < w; ++x) m.texels.push_back(normal_at(Vec2(x + 0.5, row + 0.5)).normalized().cast<float>());
  return m;
}

inline NormalMap flat_map(uint32_t w, uint32_t h) {
  return map_from(w, h, [](const Vec2&) { return Vec3(0, 0, 1); });
}

inline BakedCrease bake(const NormalMap& map, const CurveSet& curves, uint32_t iterations = 10, double band = 4.0) {
  CreaseBakeOptions o;
  o.smooth_iterations = iterations;
  o.band = band;
  return bake_crease(map, curves, o, Progress::silent());
}

// Which side of the directed line a -> b point p lies on (+1: cross(b - a, p - a) >= 0), and how far.
inline double signed_line_distance(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 d = (b - a).normalized();
  return d.x() * (p - a).y() - d.y() * (p - a).x();
}

}  // namespace mbk::test
