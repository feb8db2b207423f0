// Distance, gradient and side maps of the discontinuity network (see crease_distance.h).
#include "libbake/crease/crease_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/core/release_free_memory.h"

namespace mbk {

nlohmann::json DistanceStatistics::to_json() const {
  return {{"band", band}, {"samples_in_band", samples_in_band}, {"max_distance", max_distance}};
}

double segment_distance(const CurveSegment& s, const Vec2& p, Vec2* nearest) {
  const Vec2 d = s.b - s.a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - s.a).dot(d) / len2, 0.0, 1.0) : 0.0;
  const Vec2 q = t == 1.0 ? s.b : Vec2(s.a + t * d);
  if (nearest) *nearest = q;
  const double ex = p.x() - q.x(), ey = p.y() - q.y();
  return std::sqrt(ex * ex + ey * ey);  // no hypot: the components are texel-sized, nothing over- or underflows
}

namespace {

// Every sample's nearest segment (the smallest index on a tie, whatever order the offers come in) and its distance;
// samples sit at x = i - 0.5, y = j - 0.5.
class NearestSegments {
 public:
  NearestSegments(const std::vector<CurveSegment>& segments, int64_t nx, int64_t ny)
      : segments_(segments),
        nx_(nx),
        ny_(ny),
        dist_(size_t(nx * ny), std::numeric_limits<double>::infinity()),
        nearest_(size_t(nx * ny), -1) {
    if (segments.size() > size_t(std::numeric_limits<int32_t>::max()))
      throw Error(ExitCode::runtime_failure, "internal: more than 2^31 - 1 crease network segments");
  }

  static Vec2 position(int64_t i, int64_t j) { return Vec2(double(i) - 0.5, double(j) - 0.5); }
  const std::vector<double>& distances() const { return dist_; }
  int64_t nearest(size_t k) const { return nearest_[k]; }
  // Frees the distances (nearest() stays): the maps are then made from the nearest segments alone.
  void release_distances() { std::vector<double>().swap(dist_); }

  // Brute force over each segment's bounding box grown by the band, bands of rows in parallel: each band takes the
  // segments whose box meets it (the result does not depend on the order of the offers).
  void offer_within(double band) {
    settled_below_ = band - 1e-6;
    struct Box {
      int64_t i0, i1, j0, j1;
    };
    // A segment's box, computed where needed (not stored: the boxes of every segment were the largest array here).
    const auto box_of = [&](const CurveSegment& seg) {
      return Box{std::max<int64_t>(0, int64_t(std::ceil(std::min(seg.a.x(), seg.b.x()) - band + 0.5))),
                 std::min<int64_t>(nx_ - 1, int64_t(std::floor(std::max(seg.a.x(), seg.b.x()) + band + 0.5))),
                 std::max<int64_t>(0, int64_t(std::ceil(std::min(seg.a.y(), seg.b.y()) - band + 0.5))),
                 std::min<int64_t>(ny_ - 1, int64_t(std::floor(std::max(seg.a.y(), seg.b.y()) + band + 0.5)))};
    };
    constexpr int64_t kBandRows = 16;
    std::vector<std::vector<int32_t>> band_segments(size_t((ny_ + kBandRows - 1) / kBandRows));
    for (size_t s = 0; s < segments_.size(); ++s) {
      const Box b = box_of(segments_[s]);
      if (b.i0 > b.i1 || b.j0 > b.j1) continue;
      for (int64_t r = b.j0 / kBandRows; r <= b.j1 / kBandRows; ++r) band_segments[size_t(r)].push_back(int32_t(s));
    }
    parallel_for(0, int64_t(band_segments.size()), [&](int64_t r) {
      const int64_t first = r * kBandRows, last = std::min(ny_, first + kBandRows) - 1;
      for (int32_t s : band_segments[size_t(r)]) {
        const Box b = box_of(segments_[size_t(s)]);
        for (int64_t j = std::max(first, b.j0); j <= std::min(last, b.j1); ++j)
          for (int64_t i = b.i0; i <= b.i1; ++i) offer(i, j, s);
      }
    });
  }

  // Nearest-segment propagation beyond the band: a forward raster sweep (each sample offered its left and upper
  // neighbours' segments, then each row right to left), then the same backward.
  void propagate(Progress& progress) {
    for (int64_t j = 0; j < ny_; ++j) {
      for (int64_t i = 0; i < nx_; ++i) {
        take(i, j, i - 1, j);
        take(i, j, i - 1, j - 1);
        take(i, j, i, j - 1);
        take(i, j, i + 1, j - 1);
      }
      for (int64_t i = nx_ - 1; i >= 0; --i) take(i, j, i + 1, j);
    }
    progress.advance();
    for (int64_t j = ny_ - 1; j >= 0; --j) {
      for (int64_t i = nx_ - 1; i >= 0; --i) {
        take(i, j, i + 1, j);
        take(i, j, i + 1, j + 1);
        take(i, j, i, j + 1);
        take(i, j, i - 1, j + 1);
      }
      for (int64_t i = 0; i < nx_; ++i) take(i, j, i - 1, j);
    }
    progress.advance();
  }

 private:
  void offer(int64_t i, int64_t j, int32_t s) {
    const size_t k = size_t(j * nx_ + i);
    const double d = segment_distance(segments_[size_t(s)], position(i, j));
    if (d < dist_[k] || (d == dist_[k] && s < nearest_[k])) {
      dist_[k] = d;
      nearest_[k] = s;
    }
  }
  // Offers sample (i, j) the nearest segment of sample (ni, nj), if that is inside, has one, and the offer can
  // change anything: not when (i, j) already holds that segment (the same distance again), nor when (i, j) is
  // settled - its distance under the band (less a margin far above rounding), so that every segment as near was
  // offered by offer_within and the smallest index of the nearest already won.
  void take(int64_t i, int64_t j, int64_t ni, int64_t nj) {
    if (ni < 0 || nj < 0 || ni >= nx_ || nj >= ny_) return;
    const size_t k = size_t(j * nx_ + i);
    if (dist_[k] < settled_below_) return;
    const int32_t s = nearest_[size_t(nj * nx_ + ni)];
    if (s >= 0 && s != nearest_[k]) offer(i, j, s);
  }

  const std::vector<CurveSegment>& segments_;
  int64_t nx_, ny_;
  std::vector<double> dist_;
  std::vector<int32_t> nearest_;  // -1: none yet
  double settled_below_ = 0.0;    // set by offer_within: samples nearer than this to a segment are final
};

}  // namespace

DistanceStatistics compute_distance_maps(const std::vector<CurveSegment>& segments, double band, CreaseField& field,
                                         Progress& progress) {
  const int64_t nx = field.samples_x(), ny = field.samples_y();
  progress.start("crease: distance map", 4);
  NearestSegments found(segments, nx, ny);
  found.offer_within(band);
  progress.advance();
  DistanceStatistics stats;
  stats.band = band;
  for (double d : found.distances()) stats.samples_in_band += d <= band;
  found.propagate(progress);
  // The maps from each sample's nearest segment, rows in parallel (the largest distance per row, then over rows).
  // The maps are sized here, once the search is done and its distances freed: the bake's peak memory is then the
  // field plus the nearest-segment indices.
  found.release_distances();
  release_free_memory();  // and offer_within's per-band lists
  field.distance.assign(size_t(nx * ny), 0.0f);
  field.gradient.assign(size_t(nx * ny) * 2, 0.0f);
  field.side.assign(size_t(nx * ny), int8_t(1));
  std::vector<double> row_max(size_t(ny), 0.0);
  parallel_for(0, ny, [&](int64_t j) {
    for (int64_t i = 0; i < nx; ++i) {
      const size_t k = size_t(j * nx + i);
      const CurveSegment& seg = segments[size_t(found.nearest(k))];
      const Vec2 p = NearestSegments::position(i, j), dir = seg.b - seg.a;
      Vec2 q;
      const double d = segment_distance(seg, p, &q);
      const double cross = dir.x() * (p - seg.a).y() - dir.y() * (p - seg.a).x();
      const Vec2 g = d > 0.0 ? Vec2((p - q) / d) : Vec2(Vec2(-dir.y(), dir.x()).normalized());
      field.distance[k] = float(d);
      field.gradient[2 * k] = float(g.x());
      field.gradient[2 * k + 1] = float(g.y());
      field.side[k] = cross >= 0.0 ? 1 : -1;
      row_max[size_t(j)] = std::max(row_max[size_t(j)], d);
    }
  });
  for (double d : row_max) stats.max_distance = std::max(stats.max_distance, d);
  progress.advance();
  progress.finish();
  return stats;
}

}  // namespace mbk
