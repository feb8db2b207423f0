// `flakes`: metallic-flake paint and glitter, the sparkle case of the glint papers ([Wang20]; [Shah24]):
// a dense scattering of small flat discs, each a facet with its own random tilt, on a flat base. One flake
// per cell of a jittered lattice (periodic_cells.h), clipped by its Voronoi cell where discs would
// overlap. The map is piecewise constant and, unlike the other kinds, not the gradient of a height
// field: flakes are separate platelets, so their normals need not be integrable (tests/gen checks that the
// curl test sees this).
#include "libbake/core/hash.h"
#include "libbake/core/parallel.h"
#include "libbake/gen/generator.h"
#include "libbake/gen/hashed_disk.h"
#include "libbake/gen/height_field.h"
#include "libbake/gen/periodic_cells.h"

namespace mbk {

NormalMap generate_flakes(const MapSize& size, uint32_t seed, Progress& progress) {
  constexpr double kFlakesPerSide = 40.0, kJitter = 0.9;
  constexpr double kMaxSlope = 0.5;  // tilt up to atan(0.5) = 26.6 degrees, uniform over the slope disk
  const uint32_t cx = size.features_along(size.width, kFlakesPerSide),
                 cy = size.features_along(size.height, kFlakesPerSide);
  const uint32_t stream = hash_combine(seed, 0x666c616bu);  // "flak"
  NormalMap map;
  map.width = size.width;
  map.height = size.height;
  map.texels.resize(size_t(size.width) * size.height);
  parallel_for(0, size.height, [&](int64_t row) {
    for (uint32_t x = 0; x < size.width; ++x) {
      const CellQuery q = nearest_cells(texel_uv(x, uint32_t(row), size.width, size.height), cx, cy, kJitter, stream);
      const uint32_t h = hash4(stream, q.cell_x, q.cell_y, 0x74696c74u);  // "tilt"
      const double radius = 0.3 + 0.25 * unit_from_hash(h);               // cell units
      Vec3 n(0.0, 0.0, 1.0);
      if (q.f1 < radius) {
        const Vec2 slope = kMaxSlope * hashed_unit_disk(h);
        n = Vec3(-slope.x(), -slope.y(), 1.0).normalized();
      }
      map.at(x, uint32_t(row)) = n.cast<float>();
    }
    progress.advance();
  });
  return map;
}

}  // namespace mbk
