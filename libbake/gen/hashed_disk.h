// A point uniformly distributed in the unit disk from an integer hash, by rejection from the square with
// a chain of PCG hashes: no sin/cos, so the same point on every platform. (Expected 1.27 draws.)
#pragma once

#include <cstdint>

#include "libbake/core/eigen.h"
#include "libbake/core/hash.h"

namespace mbk {

inline Vec2 hashed_unit_disk(uint32_t h) {
  for (;;) {
    h = pcg_hash(h);
    const double a = 2.0 * unit_from_hash(h) - 1.0;
    h = pcg_hash(h);
    const double b = 2.0 * unit_from_hash(h) - 1.0;
    if (a * a + b * b <= 1.0) return {a, b};
  }
}

}  // namespace mbk
