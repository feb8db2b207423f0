// Small normal maps and loaded-map records for the filter tests: random unit normals in the upper
// hemisphere (deterministic seed), and a LoadedNormalMap wrapper with a plausible input record.
#pragma once

#include <random>

#include "libbake/image/normal_map.h"

namespace mbk::test {

inline NormalMap random_normal_map(uint32_t w, uint32_t h, uint64_t seed, double spread = 0.6) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, spread);
  NormalMap m;
  m.width = w, m.height = h;
  for (size_t i = 0; i < size_t(w) * h; ++i) m.texels.push_back(Vec3(g(rng), g(rng), 1.0).normalized().cast<float>());
  return m;
}

inline LoadedNormalMap loaded_map(NormalMap map) {
  LoadedNormalMap m;
  m.record.path = "in-memory.png";
  m.record.content_hash = "xxh3:0000000000000000";
  m.record.width = map.width, m.record.height = map.height, m.record.channels = 3;
  m.record.pixel_format = "float", m.record.convention = "+Y", m.record.invalid_policy = "error";
  m.map = std::move(map);
  return m;
}

}  // namespace mbk::test
