// `brushed`: brushed metal, the anisotropic case of the glint papers ([Wang20], [Shah24]): long, fine
// parallel streaks along u. The height field is fractal gradient noise whose lattice has kAnisotropy
// times more cells across the streaks (along v) than along them, plus a few soft bands across the whole
// map (the slow variation of brushing pressure). Slopes are therefore mostly along y: the normals fan out
// in the y-z plane.
#include "libbake/core/hash.h"
#include "libbake/gen/generator.h"
#include "libbake/gen/height_field.h"
#include "libbake/gen/periodic_noise.h"

namespace mbk {

NormalMap generate_brushed(const MapSize& size, uint32_t seed, Progress& progress) {
  constexpr double kStreaksPerSide = 96.0, kAnisotropy = 48.0, kBandsPerSide = 3.0;
  constexpr double kGain = 0.6, kBandWeight = 0.6, kRmsSlope = 0.15;
  const uint32_t sy = size.features_along(size.height, kStreaksPerSide);
  const uint32_t sx = size.features_along(size.width, kStreaksPerSide / kAnisotropy);
  const uint32_t by = size.features_along(size.height, kBandsPerSide), bx = size.features_along(size.width, 1.0);
  const int octaves = octaves_resolved(sy, size.height, 4);
  const uint32_t streaks = hash_combine(seed, 0x73747265u), bands = hash_combine(seed, 0x62616e64u);
  const HeightField field = sample_height_field(
      size.width, size.height,
      [&](uint32_t x, uint32_t row) {
        const Vec2 uv = texel_uv(x, row, size.width, size.height);
        // The streak term's amplitude shrinks with its frequency (as a height), so the bands, broad but
        // low in slope, get a large weight to show at all.
        return periodic_fbm(uv, sx, sy, octaves, kGain, streaks) +
               kBandWeight * double(sy) / by * periodic_fbm(uv, bx, by, 2, 0.5, bands) / kAnisotropy;
      },
      progress);
  return normals_with_rms_slope(field, kRmsSlope);
}

}  // namespace mbk
