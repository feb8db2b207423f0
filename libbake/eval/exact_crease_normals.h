// The ground truth of the `crease` effect (what `render --reference` shows, crease_effect.h): the normal of a
// map with discontinuities at an exact point, computed from the raw inputs alone - the normal map's texels and
// the curves as drawn - without the bake's simplification, distance and gradient maps or cell partition.
//   Normal:   bilinear interpolation of the four texel centres around the point, restricted to the centres the
//             point sees without crossing a curve (the segment from the point to the centre meets no curve
//             segment), weights renormalised; when it sees none of the four, the nearest visible centre of the
//             surrounding 4 x 4, else the nearest of the four. Lattice centres beyond the map are the edge
//             texel (clamp-to-edge, as the crease asset's ring of samples), seen where that texel is.
//   Distance: exact Euclidean distance to the nearest curve segment; gradient the unit vector from that nearest
//             point to the point; side +1 when the point is right of that directed segment (y down).
//   Profile:  [Parilov05] Eq. (1) (formats/crease_reconstruction.h crease_normal) with these exact values.
// This is what the reconstruction of Sec. 4.3 approximates, so the difference between the two is the method's
// error (simplification to the allowed cell configurations, interpolated distances and gradients).
// Coordinates: texel coordinates of libbake/crease/curve_set.h (x right, y down, the map [0, W] x [0, H]).
#pragma once

#include <optional>
#include <vector>

#include "formats/crease_reconstruction.h"
#include "libbake/core/eigen.h"
#include "libbake/crease/curve_set.h"
#include "libbake/image/normal_map.h"

namespace mbk {

class ExactCreaseNormals {
 public:
  ExactCreaseNormals(NormalMap map, std::vector<CurveSegment> segments, std::optional<CreaseProfile> profile);

  // The unit tangent-space normal (+Y) at texel point p.
  Vec3 normal(const Vec2& p) const;
  // The exact distance, gradient, side and side-aware map normal at p (crease_normal's input). The distance is
  // +infinity when no segment is within reach(): the profile is flat there and the side does not matter.
  CreaseSample sample(const Vec2& p) const;
  // How far from a curve the distance is computed: the profile's width and blend end, and at least the 1.5
  // texels within which a curve can hide one of the four nearest texel centres from a point.
  double reach() const { return reach_; }
  uint32_t width() const { return map_.width; }
  uint32_t height() const { return map_.height; }

 private:
  // The segments whose box, grown by max(reach_, visibility_reach_), holds p: every segment within either.
  const std::vector<uint32_t>& candidates(const Vec2& p) const;
  bool visible(const Vec2& p, const Vec2& centre, const std::vector<uint32_t>& near) const;
  Vec3 side_aware_normal(const Vec2& p, const std::vector<uint32_t>& near) const;

  NormalMap map_;
  std::vector<CurveSegment> segments_;
  std::optional<CreaseProfile> profile_;
  double reach_ = 1.5;
  double visibility_reach_ = 0.0;
  // Uniform grid of buckets over the map, each listing the segments whose grown box overlaps it.
  double bucket_ = 4.0;
  uint32_t buckets_x_ = 1, buckets_y_ = 1;
  std::vector<std::vector<uint32_t>> buckets_;
};

}  // namespace mbk
