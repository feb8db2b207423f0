// `bumps`: isotropic bumps, the generic rough surface (e.g. the bumpy/plastic examples of [Wang20] and
// [Han07]): a fractal sum of tileable gradient noise used as a height field. Coarse octaves dominate
// (gain 0.33 per octave, less than the 0.5 at which every octave would add equal slope), so the map reads
// as bumps with finer roughness on top rather than as white noise.
#include "libbake/core/hash.h"
#include "libbake/gen/generator.h"
#include "libbake/gen/height_field.h"
#include "libbake/gen/periodic_noise.h"

namespace mbk {

NormalMap generate_bumps(const MapSize& size, uint32_t seed, Progress& progress) {
  constexpr double kBumpsPerSide = 6.0, kGain = 0.33, kRmsSlope = 0.3;  // RMS tilt about 17 degrees
  const uint32_t cx = size.features_along(size.width, kBumpsPerSide),
                 cy = size.features_along(size.height, kBumpsPerSide);
  const int octaves = std::min(octaves_resolved(cx, size.width, 6), octaves_resolved(cy, size.height, 6));
  const uint32_t stream = hash_combine(seed, 0x62756d70u);  // "bump"
  const HeightField field = sample_height_field(
      size.width, size.height,
      [&](uint32_t x, uint32_t row) {
        return periodic_fbm(texel_uv(x, row, size.width, size.height), cx, cy, octaves, kGain, stream);
      },
      progress);
  return normals_with_rms_slope(field, kRmsSlope);
}

}  // namespace mbk
