// Pixels a silhouette crosses (see silhouette_pixels.h).
#include "libbake/eval/silhouette_pixels.h"

#include "libbake/core/parallel.h"
#include "libbake/eval/shape_intersection.h"

namespace mbk {

std::vector<uint8_t> silhouette_pixels(const Scene& scene, const PinholeCamera& camera) {
  const uint32_t w = camera.width(), h = camera.height(), corners_w = w + 1;
  // What each corner's ray sees: the shape's index, or -1 for the background.
  std::vector<int64_t> seen(size_t(corners_w) * (h + 1));
  parallel_for(0, int64_t(h) + 1, [&](int64_t y) {
    for (uint32_t x = 0; x <= w; ++x) {
      const auto hit = intersect_scene(scene.shapes, camera.ray(double(x), double(y)).ray);
      seen[size_t(y) * corners_w + x] = hit ? int64_t(hit->shape) : -1;
    }
  });
  std::vector<uint8_t> edge(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const int64_t* c = &seen[size_t(y) * corners_w + x];
      edge[size_t(y) * w + x] = !(c[0] == c[1] && c[0] == c[corners_w] && c[0] == c[corners_w + 1]);
    }
  return edge;
}

}  // namespace mbk
