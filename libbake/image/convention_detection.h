// Telling a normal map's green-channel convention (+Y or -Y) from the map itself, by integrability.
//
// The math. A normal map made from a height field h has the slope field (p, q) = (-n_x / n_z, -n_y / n_z) =
// grad h (x right, y up), and a gradient field is curl-free: dq/dx - dp/dy = 0. Reading a -Y map as +Y negates
// q, which leaves the curl -dq/dx - dp/dy: only one of the two readings is integrable. With a = dq/dx and
// b = dp/dy by central differences at a texel (y up: d/dy is row - 1 minus row + 1), the curl energies of the two
// readings over the map are
//     E(+Y) = sum (a - b)^2,    E(-Y) = sum (-a - b)^2 = sum (a + b)^2,
// and the statistic is their normalised difference
//     s = (E(-Y) - E(+Y)) / (E(-Y) + E(+Y)) = 2 sum ab / sum (a^2 + b^2),    in [-1, 1]:
// +1 for an exact +Y height field, -1 for an exact -Y one, near 0 when neither reading is integrable (flakes:
// separately tilted facets) or when the map has no mixed slope variation (flat maps, ridges along an axis).
// The energy ratio of the wrong reading to the right one is (1 + |s|) / (1 - |s|). s is scale-free: scaling the
// slopes (a bumpier or flatter map of the same shape) or the normals' lengths (slopes are ratios of components)
// leaves it unchanged; flipping the green channel negates it.
//
// Confidence. If a and b were unrelated (the null hypothesis: no height field behind the map) and the stencils
// independent, the standard deviation of s would be at most 1 / sqrt(n_eff), where
// n_eff = (sum w)^2 / sum w^2, w = a^2 + b^2, counts the stencils the curl energy is spread over (n for an even
// spread, 1 when one stencil carries it all). Neighbouring stencils share texels, so the spread is wider than
// that; a reading is decided when |s| >= max(kConventionMinConfidence, kConventionNullSigmas / sqrt(n_eff))
// (both constants measured on the generated kinds and on real maps: docs/NORMAL_MAPS.md "Green-channel convention"),
// else the map is undecidable.
//
// Stencils: every texel with a neighbour on each side, borders clamped, never wrapped (a map that does not tile
// would add a seam of curl); maps narrower or shorter than 3 texels have none and are undecidable. Stencils
// touching a texel at the horizon (n_z < kConventionMinZ: slopes steeper than 87 degrees, unbounded at n_z = 0,
// e.g. repaired texels) are left out. One pass over the rows in parallel, summed in row order: deterministic.
#pragma once

#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

#include "libbake/image/normal_map.h"

namespace mbk {

// Between the weakest real height field (leather_grain, |s| = 0.43; the generated ones and the lossless real maps
// have 0.93 or more) and the strongest non-integrable map measured (a 16 x 16 flakes map, 0.08).
inline constexpr double kConventionMinConfidence = 0.25;
// |s| sqrt(n_eff) reached 2.4 at most on flakes and random normals; 6 allows for stencils that share texels.
inline constexpr double kConventionNullSigmas = 6.0;
inline constexpr float kConventionMinZ = 0.05f;

struct ConventionEvidence {
  double statistic = 0.0;           // s: > 0 favours +Y, < 0 favours -Y (the map as decoded from its file, as +Y)
  double effective_stencils = 0.0;  // n_eff
  uint64_t stencils = 0;            // stencils used
  // The |s| a decision needs: max(kConventionMinConfidence, kConventionNullSigmas / sqrt(max(1, n_eff))); above 1,
  // out of reach, when n_eff < kConventionNullSigmas^2 (too little evidence).
  double required_confidence() const;
  // The convention the statistic is confident about, or nullopt (undecidable).
  std::optional<YConvention> verdict() const;
  nlohmann::json to_json() const;  // {statistic, confidence (|s|), required_confidence, effective_stencils, stencils}
};

// The evidence of a map decoded as +Y (its file's green channel as stored).
ConventionEvidence measure_convention(const NormalMap& map);

}  // namespace mbk
