// `leather`: pebbled leather grain, the cellular structure of the multiscale synthesis examples ([Han08])
// and a mid-roughness case for filtering ([Han07]): irregular rounded cells separated by narrow creases,
// with a fine grain on top. Height of a cell: a rounded shoulder rising from the crease (the distance to
// the cell's edge, periodic_cells.h) to a gently domed top, plus low-amplitude fractal noise.
#include <algorithm>

#include "libbake/core/hash.h"
#include "libbake/gen/generator.h"
#include "libbake/gen/height_field.h"
#include "libbake/gen/periodic_cells.h"
#include "libbake/gen/periodic_noise.h"

namespace mbk {

NormalMap generate_leather(const MapSize& size, uint32_t seed, Progress& progress) {
  constexpr double kCellsPerSide = 32.0, kJitter = 1.0;
  constexpr double kWarp = 0.35;      // cell units: bends the Voronoi edges into irregular, rounded outlines
  constexpr double kShoulder = 0.35;  // cell units from the crease to the top
  constexpr double kDome = 0.5, kGrain = 0.08, kRmsSlope = 0.25;
  const uint32_t cx = size.features_along(size.width, kCellsPerSide),
                 cy = size.features_along(size.height, kCellsPerSide);
  const uint32_t wx = std::max(1u, cx / 4), wy = std::max(1u, cy / 4);
  const uint32_t gx = cx * 3, gy = cy * 3;
  const int warp_octaves = std::min(octaves_resolved(wx, size.width, 3), octaves_resolved(wy, size.height, 3));
  const int grain_octaves = std::min(octaves_resolved(gx, size.width, 2), octaves_resolved(gy, size.height, 2));
  const uint32_t cells = hash_combine(seed, 0x6c656174u), warp = hash_combine(seed, 0x77617270u);  // "leat", "warp"
  const uint32_t grain = hash_combine(seed, 0x67726169u);                                          // "grai"
  const HeightField field = sample_height_field(
      size.width, size.height,
      [&](uint32_t x, uint32_t row) {
        const Vec2 uv = texel_uv(x, row, size.width, size.height);
        // Periodic noise displaces where the cells are looked up; the height stays a function of position.
        const Vec2 bend(periodic_fbm(uv, wx, wy, warp_octaves, 0.5, warp) / cx,
                        periodic_fbm(uv, wx, wy, warp_octaves, 0.5, warp + 1) / cy);
        const CellQuery q = nearest_cells(uv + kWarp * bend, cx, cy, kJitter, cells);
        const double s = 1.0 - std::min(q.border / kShoulder, 1.0);
        return (1.0 - s * s) - kDome * q.f1 * q.f1 + kGrain * periodic_fbm(uv, gx, gy, grain_octaves, 0.5, grain);
      },
      progress);
  return normals_with_rms_slope(field, kRmsSlope);
}

}  // namespace mbk
