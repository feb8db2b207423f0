// The `panels` generator and its crease lines (see panels.h).
//
// Layout: a grid of about 4 cells per longest side; a hash splits each cell into one panel, two halves
// (either way) or four quarters, each inset by half the groove width. Half of the panels get a recessed
// inset: a rectangle falling by a smaller bevel, placed on the panel's flat top with a margin, so that
// the contributions of the two rectangles never overlap and every crease stays a straight segment.
// A split or an inset is made only when the pieces keep a flat top (side > 2 bevels + margin); a whole
// cell on a map of a few texels may be narrower than two bevels, which panel_creases handles (hip roof).
#include "libbake/gen/panels.h"

#include <algorithm>
#include <cmath>

#include "libbake/core/hash.h"
#include "libbake/gen/height_field.h"

namespace mbk {
namespace {

double inside_distance(const BevelledRect& r, const Vec2& p) {
  return std::min({p.x() - r.lo.x(), r.hi.x() - p.x(), p.y() - r.lo.y(), r.hi.y() - p.y()});
}

// Height at p (texel units): the sum of the rectangles' contributions; zero in the grooves.
double panel_height(const PanelLayout& layout, const Vec2& p) {
  double h = 0.0;
  for (const BevelledRect& r : layout.rects) h += r.rise * std::clamp(inside_distance(r, p), 0.0, r.bevel);
  return h;
}

bool has_flat_top(const Vec2& lo, const Vec2& hi, double bevel, double margin) {
  return hi.x() - lo.x() > 2.0 * bevel + margin && hi.y() - lo.y() > 2.0 * bevel + margin;
}

}  // namespace

PanelLayout panel_layout(const MapSize& size, uint32_t seed) {
  constexpr double kCellsPerSide = 4.0;
  PanelLayout layout;
  layout.width = size.width;
  layout.height = size.height;
  const double S = size.longest();
  const uint32_t cx = size.features_along(size.width, kCellsPerSide),
                 cy = size.features_along(size.height, kCellsPerSide);
  const double cw = double(size.width) / cx, ch = double(size.height) / cy;
  const double gap = 0.5 * std::max(1.0, S / 128.0);  // half the groove width
  const double bevel = S / 80.0, inset_bevel = 0.6 * bevel, margin = 1.5 * bevel;
  const uint32_t stream = hash_combine(seed, 0x70616e65u);  // "pane"
  for (uint32_t j = 0; j < cy; ++j)
    for (uint32_t i = 0; i < cx; ++i) {
      const uint32_t h = hash3(stream, i, j);
      const uint32_t split = h % 4;  // 0 whole, 1 left|right, 2 top/bottom, 3 quarters
      const uint32_t nx = (split == 1 || split == 3) ? 2 : 1, ny = (split == 2 || split == 3) ? 2 : 1;
      const Vec2 cell_lo(i * cw, j * ch);
      const Vec2 piece(cw / nx, ch / ny);
      const bool can_split = has_flat_top(Vec2::Zero(), piece - Vec2::Constant(2.0 * gap), bevel, margin);
      const uint32_t px = can_split ? nx : 1, py = can_split ? ny : 1;
      for (uint32_t b = 0; b < py; ++b)
        for (uint32_t a = 0; a < px; ++a) {
          const Vec2 lo = cell_lo + Vec2(a * cw / px, b * ch / py) + Vec2::Constant(gap);
          const Vec2 hi = cell_lo + Vec2((a + 1) * cw / px, (b + 1) * ch / py) - Vec2::Constant(gap);
          if (!(hi.x() > lo.x() && hi.y() > lo.y())) continue;  // a map too small for any panel stays flat
          layout.rects.push_back({lo, hi, bevel, 1.0});
          const uint32_t hp = hash3(h, a, b);
          const Vec2 ilo = lo + Vec2::Constant(bevel + margin), ihi = hi - Vec2::Constant(bevel + margin);
          if (hp % 2 == 0 && has_flat_top(ilo, ihi, inset_bevel, margin) && has_flat_top(lo, hi, bevel, 0.0))
            layout.rects.push_back({ilo, ihi, inset_bevel, -1.0});
        }
    }
  return layout;
}

std::vector<CreaseSegment> panel_creases(const PanelLayout& layout) {
  std::vector<CreaseSegment> out;
  auto outline = [&](const Vec2& lo, const Vec2& hi) {
    out.push_back({{lo.x(), lo.y()}, {hi.x(), lo.y()}});
    out.push_back({{hi.x(), lo.y()}, {hi.x(), hi.y()}});
    out.push_back({{hi.x(), hi.y()}, {lo.x(), hi.y()}});
    out.push_back({{lo.x(), hi.y()}, {lo.x(), lo.y()}});
  };
  for (const BevelledRect& r : layout.rects) {
    // The bevel ends `inset` inside the outline. A rectangle narrower than two bevels (only on maps of a few
    // texels) has no flat top: it is a hip roof, d never reaches the bevel, and the inner outline collapses
    // to its ridge, a segment (or a point) half the narrow side inside; the mitres still run at 45 degrees.
    const double inset = std::min(r.bevel, 0.5 * std::min(r.hi.x() - r.lo.x(), r.hi.y() - r.lo.y()));
    const Vec2 ilo = r.lo + Vec2::Constant(inset), ihi = r.hi - Vec2::Constant(inset);
    outline(r.lo, r.hi);
    if (ihi.x() > ilo.x() && ihi.y() > ilo.y())
      outline(ilo, ihi);
    else if (ihi.x() > ilo.x() || ihi.y() > ilo.y())
      out.push_back({ilo, ihi});  // the ridge line
    out.push_back({r.lo, ilo});
    out.push_back({{r.hi.x(), r.lo.y()}, {ihi.x(), ilo.y()}});
    out.push_back({r.hi, ihi});
    out.push_back({{r.lo.x(), r.hi.y()}, {ilo.x(), ihi.y()}});
  }
  return out;
}

Vec3 panel_normal(const PanelLayout& layout, const Vec2& p) {
  // dh/dx and dh/drow: each rectangle contributes rise * grad(inside distance) where 0 < d < bevel; the
  // inside distance is the smallest of the four edge distances, whose gradient is that edge's inward normal.
  Vec2 g = Vec2::Zero();
  for (const BevelledRect& r : layout.rects) {
    const double d[4] = {p.x() - r.lo.x(), r.hi.x() - p.x(), p.y() - r.lo.y(), r.hi.y() - p.y()};
    const Vec2 inward[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    const int k = int(std::min_element(d, d + 4) - d);
    if (d[k] > 0.0 && d[k] < r.bevel) g += r.rise * inward[k];
  }
  return Vec3(-g.x(), g.y(), 1.0).normalized();  // tangent y is up: dh/dv = -dh/drow
}

std::vector<CreaseSegment> panel_creases(const MapSize& size, uint32_t seed) {
  return panel_creases(panel_layout(size, seed));
}

NormalMap generate_panels(const MapSize& size, uint32_t seed, Progress& progress) {
  const PanelLayout layout = panel_layout(size, seed);
  const HeightField field = sample_height_field(
      size.width, size.height, [&](uint32_t x, uint32_t row) { return panel_height(layout, Vec2(x + 0.5, row + 0.5)); },
      progress);
  return normals_from_height(field, 1.0);  // bevels rise one texel per texel: 45 degrees
}

}  // namespace mbk
