// `scratches`: sparse sharp lines on a flat surface, the scratched-metal case of the glint papers
// ([Wang20]; [Shah24]). Each scratch is a straight V-groove (constant wall slope) whose width tapers to
// zero at both ends; overlapping grooves keep the deepest. Most texels stay exactly (0, 0, 1): a hard case
// of identical normals for every technique that sorts or clusters them. Grooves wrap at the borders.
#include <algorithm>
#include <cmath>

#include "libbake/core/hash.h"
#include "libbake/gen/generator.h"
#include "libbake/gen/hashed_disk.h"
#include "libbake/gen/height_field.h"

namespace mbk {
namespace {

struct Groove {
  Vec2 a, d;          // from a to a + d, continuous texel coordinates (x right, row down)
  double half_width;  // texels, at the middle of the scratch
  double wall_slope;  // depth change per texel across the groove
  Vec2 lo, hi;        // bounding box including the width
};

// The scratches and their periodic copies that touch the map.
std::vector<Groove> place_grooves(const MapSize& size, uint32_t seed) {
  constexpr double kScratchesPerSquare = 40.0;  // on a square map; scaled with the area otherwise
  const double W = size.width, H = size.height, S = size.longest();
  const int count = std::max(1, int(std::floor(kScratchesPerSquare * W * H / (S * S) + 0.5)));
  const double base_width = std::max(0.75, S / 400.0);
  std::vector<Groove> grooves;
  for (int i = 0; i < count; ++i) {
    const uint32_t h = hash_combine(seed, uint32_t(i));
    Groove g;
    g.a = {unit_from_hash(hash_combine(h, 1)) * W, unit_from_hash(hash_combine(h, 2)) * H};
    Vec2 dir = hashed_unit_disk(hash_combine(h, 3));
    if (dir.squaredNorm() == 0.0) dir = Vec2(1, 0);  // the disk's exact centre has no direction
    g.d = dir.normalized() * S * (0.08 + 0.35 * unit_from_hash(hash_combine(h, 4)));
    // At most 0.45 of the map along each axis, so that the 3 x 3 periodic copies below are all it needs.
    const double shrink =
        std::min({1.0, 0.45 * W / std::max(std::abs(g.d.x()), 1e-300), 0.45 * H / std::max(std::abs(g.d.y()), 1e-300)});
    g.d *= shrink;
    g.half_width = base_width * (0.7 + 0.6 * unit_from_hash(hash_combine(h, 5)));
    g.wall_slope = 0.5 + 0.7 * unit_from_hash(hash_combine(h, 6));
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        Groove c = g;
        c.a += Vec2(ox * W, oy * H);
        c.lo = c.a.cwiseMin(c.a + c.d) - Vec2::Constant(c.half_width);
        c.hi = c.a.cwiseMax(c.a + c.d) + Vec2::Constant(c.half_width);
        if (c.hi.x() >= 0 && c.lo.x() <= W && c.hi.y() >= 0 && c.lo.y() <= H) grooves.push_back(c);
      }
  }
  return grooves;
}

// Height of one groove at p (<= 0): a V whose half-width narrows as sqrt(6 t (1 - t)) near the ends.
double groove_height(const Groove& g, const Vec2& p) {
  const double t = std::clamp((p - g.a).dot(g.d) / g.d.squaredNorm(), 0.0, 1.0);
  const double dist = (p - g.a - t * g.d).norm();
  const double w = g.half_width * std::sqrt(std::min(1.0, 6.0 * t * (1.0 - t)));
  return dist < w ? -g.wall_slope * (w - dist) : 0.0;
}

}  // namespace

NormalMap generate_scratches(const MapSize& size, uint32_t seed, Progress& progress) {
  const std::vector<Groove> grooves = place_grooves(size, hash_combine(seed, 0x73637261u));  // "scra"
  const HeightField field = sample_height_field(
      size.width, size.height,
      [&](uint32_t x, uint32_t row) {
        const Vec2 p(x + 0.5, row + 0.5);
        double h = 0.0;
        for (const Groove& g : grooves)
          if (p.y() >= g.lo.y() && p.y() <= g.hi.y() && p.x() >= g.lo.x() && p.x() <= g.hi.x())
            h = std::min(h, groove_height(g, p));
        return h;
      },
      progress);
  // Wall slopes are set in texel units already: scale 1.
  return normals_from_height(field, 1.0);
}

}  // namespace mbk
