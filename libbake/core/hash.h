// Integer hashing for everything procedural (noise, jitter, patch offsets): PCG-style permutations of
// 32-bit integers, identical on every compiler and platform (float `sin` hashes are not).
// Reference: Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 2020 (pcg, pcg3d).
#pragma once

#include <cstdint>

namespace mbk {

inline uint32_t pcg_hash(uint32_t v) {
  uint32_t state = v * 747796405u + 2891336453u;
  uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Hash of several integers (seed, coordinates, stream) by chaining.
inline uint32_t hash_combine(uint32_t a, uint32_t b) { return pcg_hash(a ^ (b + 0x9e3779b9u + (a << 6) + (a >> 2))); }
inline uint32_t hash3(uint32_t a, uint32_t b, uint32_t c) { return hash_combine(hash_combine(pcg_hash(a), b), c); }
inline uint32_t hash4(uint32_t a, uint32_t b, uint32_t c, uint32_t d) { return hash_combine(hash3(a, b, c), d); }

// Uniform in [0, 1) from the top 24 bits (exact in float and double).
inline double unit_from_hash(uint32_t h) { return double(h >> 8) * (1.0 / 16777216.0); }

}  // namespace mbk
