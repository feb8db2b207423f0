// `panels`: a grid of panels with 45-degree bevels and recessed insets, the sharp-crease case of
// normal maps with discontinuities ([Parilov05]) and a hard case for every filter. The geometry is a set
// of bevelled rectangles; both the height field (and so the normal map) and the exact crease lines are
// derived from it, so a crease-aware technique can be checked against the truth.
//
// Coordinates: continuous texel coordinates, x to the right and y = row downwards, the map spanning
// [0, W] x [0, H]; texel (x, row) has its centre at (x + 0.5, row + 0.5). Rectangles lie inside the map
// (the grid's cell borders include the map's borders, so the pattern tiles with a groove at the seam).
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/gen/generator.h"

namespace mbk {

// A rectangle whose border rises (rise = +1) or falls (rise = -1) at slope 1 over `bevel` texels inward:
// it adds rise * clamp(d, 0, bevel) to the height, d = distance inside the nearest edge (negative outside).
struct BevelledRect {
  Vec2 lo, hi;  // corners, lo < hi
  double bevel;
  double rise;
};

struct PanelLayout {
  uint32_t width = 0, height = 0;
  std::vector<BevelledRect> rects;  // panels (rise +1) and the insets inside some of them (rise -1)
};

PanelLayout panel_layout(const MapSize& size, uint32_t seed);

struct CreaseSegment {
  Vec2 a, b;  // end points, continuous texel coordinates as above
};

// Every line along which the panel surface's slope jumps: for each rectangle its outline, the inner
// outline where the bevel meets the flat top, and the four mitre lines joining their corners.
std::vector<CreaseSegment> panel_creases(const PanelLayout& layout);
std::vector<CreaseSegment> panel_creases(const MapSize& size, uint32_t seed);

// The exact unit normal of the panel surface at p (texel coordinates as above; tangent space, +Y: the map's
// convention), the truth the texel normals sample. On a crease line itself (measure zero) it is the normal of
// one of the two sides.
Vec3 panel_normal(const PanelLayout& layout, const Vec2& p);

}  // namespace mbk
