// Exact crease normals from the raw map and curves (see exact_crease_normals.h).
#include "libbake/eval/exact_crease_normals.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mbk {
namespace {

// Twice the signed area of (a, b, c): > 0 when c is right of a -> b as seen on screen (y down).
double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

}  // namespace

ExactCreaseNormals::ExactCreaseNormals(NormalMap map, std::vector<CurveSegment> segments,
                                       std::optional<CreaseProfile> profile)
    : map_(std::move(map)), segments_(std::move(segments)), profile_(std::move(profile)) {
  if (profile_) reach_ = std::max({reach_, profile_->width, profile_->blend_end});
  visibility_reach_ = 2.0 * std::sqrt(2.0) + 1e-9;  // the farthest centre of the 4 x 4 fallback
  const double listed = std::max(reach_, visibility_reach_);
  reach_ += 1e-9;  // a point exactly at the reach still lists its segment
  bucket_ = std::max(4.0, std::ceil(listed));
  buckets_x_ = uint32_t(std::ceil(map_.width / bucket_)) + 1;
  buckets_y_ = uint32_t(std::ceil(map_.height / bucket_)) + 1;
  buckets_.resize(size_t(buckets_x_) * buckets_y_);
  const auto bucket_of = [&](double v, uint32_t n) {
    return uint32_t(std::clamp(std::floor(v / bucket_), 0.0, double(n - 1)));
  };
  for (uint32_t s = 0; s < segments_.size(); ++s) {
    const Vec2 lo = segments_[s].a.cwiseMin(segments_[s].b), hi = segments_[s].a.cwiseMax(segments_[s].b);
    for (uint32_t by = bucket_of(lo.y() - listed, buckets_y_); by <= bucket_of(hi.y() + listed, buckets_y_); ++by)
      for (uint32_t bx = bucket_of(lo.x() - listed, buckets_x_); bx <= bucket_of(hi.x() + listed, buckets_x_); ++bx)
        buckets_[size_t(by) * buckets_x_ + bx].push_back(s);
  }
}

const std::vector<uint32_t>& ExactCreaseNormals::candidates(const Vec2& p) const {
  const auto index = [&](double v, uint32_t n) {
    return uint32_t(std::clamp(std::floor(v / bucket_), 0.0, double(n - 1)));
  };
  return buckets_[size_t(index(p.y(), buckets_y_)) * buckets_x_ + index(p.x(), buckets_x_)];
}

// The point sees the centre unless a segment has the two on different sides of its line and itself meets the
// line through them between them. Sides follow the side map's rule (orient >= 0 is side +1), so a centre exactly
// on a curve (a 45-degree crease through texel centres) belongs to side +1 only, as the bake's crossings, kept
// off the samples, put every sample on one side (test: ExactCreaseNormals.CentresOnACurveBelongToOneSide).
bool ExactCreaseNormals::visible(const Vec2& p, const Vec2& centre, const std::vector<uint32_t>& near) const {
  for (uint32_t s : near) {
    const Vec2 &a = segments_[s].a, &b = segments_[s].b;
    if ((orient(a, b, p) >= 0.0) == (orient(a, b, centre) >= 0.0)) continue;
    const double o3 = orient(p, centre, a), o4 = orient(p, centre, b);
    if (o3 * o4 <= 0.0) return false;
  }
  return true;
}

Vec3 ExactCreaseNormals::side_aware_normal(const Vec2& p, const std::vector<uint32_t>& near) const {
  // Clamp-to-edge: a lattice point beyond the map is the edge texel, seen (or not) where that texel is.
  const auto clamp_x = [&](int64_t i) { return std::clamp<int64_t>(i, 0, map_.width - 1); };
  const auto clamp_y = [&](int64_t j) { return std::clamp<int64_t>(j, 0, map_.height - 1); };
  const auto texel = [&](int64_t i, int64_t j) {
    return map_.texels[size_t(clamp_y(j)) * map_.width + size_t(clamp_x(i))].cast<double>().eval();
  };
  const auto centre = [&](int64_t i, int64_t j) { return Vec2(double(clamp_x(i)) + 0.5, double(clamp_y(j)) + 0.5); };
  const double fx = p.x() - 0.5, fy = p.y() - 0.5;
  const int64_t x0 = int64_t(std::floor(fx)), y0 = int64_t(std::floor(fy));
  const double ax = fx - double(x0), ay = fy - double(y0);
  Vec3 sum = Vec3::Zero();
  double weight = 0.0, best_weight = -1.0;
  Vec3 best = Vec3::UnitZ();
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const double w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay);
      const Vec3 n = texel(x0 + dx, y0 + dy);
      if (w > best_weight) best_weight = w, best = n;
      if (w > 0.0 && visible(p, centre(x0 + dx, y0 + dy), near)) sum += w * n, weight += w;
    }
  if (weight > 0.0 && sum.norm() > 0.0) return sum.normalized();
  double nearest = std::numeric_limits<double>::infinity();
  for (int64_t j = y0 - 1; j <= y0 + 2; ++j)
    for (int64_t i = x0 - 1; i <= x0 + 2; ++i) {
      const double d2 = (centre(i, j) - p).squaredNorm();
      if (d2 < nearest && visible(p, centre(i, j), near)) nearest = d2, best = texel(i, j);
    }
  return best.normalized();
}

CreaseSample ExactCreaseNormals::sample(const Vec2& p) const {
  const std::vector<uint32_t>& near = candidates(p);
  CreaseSample s;
  const Vec3 n = side_aware_normal(p, near);
  for (int c = 0; c < 3; ++c) s.normal[c] = n[c];
  s.distance = std::numeric_limits<double>::infinity();
  for (uint32_t k : near) {
    const Vec2 &a = segments_[k].a, &b = segments_[k].b;
    const Vec2 ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const Vec2 q = a + t * ab;
    const double d = (p - q).norm();
    if (!(d < s.distance)) continue;
    s.distance = d;
    s.side = orient(a, b, p) >= 0.0 ? 1 : -1;
    // Away from the nearest point; on the curve itself, the segment's normal towards the point's side.
    const Vec2 g = d > 0.0 ? Vec2((p - q) / d) : Vec2(Vec2(-ab.y(), ab.x()).normalized() * double(s.side));
    s.gradient[0] = g.x();
    s.gradient[1] = g.y();
  }
  if (s.distance > reach_) s.distance = std::numeric_limits<double>::infinity();
  return s;
}

Vec3 ExactCreaseNormals::normal(const Vec2& p) const {
  const CreaseSample s = sample(p);
  if (!profile_) return Vec3(s.normal[0], s.normal[1], s.normal[2]);
  double out[3];
  crease_normal(s, *profile_, out);
  return Vec3(out[0], out[1], out[2]);
}

}  // namespace mbk
