// [Parilov05] Sec. 4.2, the distance map and the gradient map of the simplified discontinuity network, at the
// lattice samples of formats/crease_field.h, and the side map.
//
// Method. Exact brute force near features (the paper's "rectangular subgrid which completely covers the
// segment"): for every network segment, every sample within `band` texels of its bounding box gets the exact
// Euclidean distance to it, and keeps the smallest (ties: the earlier segment). So every sample whose distance
// is <= band is exact. Beyond the band, the nearest segment is propagated by two raster sweeps (forward:
// neighbours left, up-left, up, up-right, then right; backward: the mirror), each sample keeping the candidate
// segment of its neighbours at the exact smallest distance: an upper bound of the true distance, equal to it
// unless the nearest segment's region of influence misses all of a sample's neighbours (tests measure the
// worst case). The gradient at a sample is the unit vector from its nearest point towards it (the gradient of
// the distance); a sample exactly on a segment takes the segment's normal on side +1.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "formats/crease_field.h"
#include "libbake/core/progress.h"
#include "libbake/crease/curve_set.h"

namespace mbk {

struct DistanceStatistics {
  double band = 0.0;
  uint64_t samples_in_band = 0;  // samples whose distance is exact by brute force
  double max_distance = 0.0;
  nlohmann::json to_json() const;
};

// Exact distance from p to segment s, and the nearest point.
double segment_distance(const CurveSegment& s, const Vec2& p, Vec2* nearest = nullptr);

// Sizes and fills field.distance, gradient (unsmoothed) and side from the network segments (the field's lattice
// allocated). band > 0. segments must not be empty.
DistanceStatistics compute_distance_maps(const std::vector<CurveSegment>& segments, double band, CreaseField& field,
                                         Progress& progress);

}  // namespace mbk
