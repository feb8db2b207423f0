// Example maps for the hard case of histogram-preserving blending: distributions with atoms. Maps whose texels are
// 50%, 75%, 90% and 99% one tilted normal (in hashed places; the rest `gen bumps`), a two-valued map (60/40), and
// a constant map. Shared by the standardization and blended-field tests.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "libbake/core/hash.h"
#include "libbake/gen/generator.h"
#include "libbake/image/normal_map.h"

namespace mbk::test {

inline NormalMap map_of(uint32_t w, uint32_t h, const std::function<Vec3f(uint32_t, uint32_t)>& normal) {
  NormalMap m{w, h, {}};
  for (uint32_t row = 0; row < h; ++row)
    for (uint32_t x = 0; x < w; ++x) m.texels.push_back(normal(x, row).normalized());
  return m;
}

struct AtomMap {
  std::string name;
  NormalMap map;
};

inline std::vector<AtomMap> atom_maps(uint32_t side = 128) {
  std::vector<AtomMap> maps;
  const NormalMap bumps = generate_normal_map("bumps", {side, side}, 5, Progress::silent());
  const Vec3f atom = Vec3f(0.12f, -0.07f, 1.0f).normalized();
  for (double fraction : {0.5, 0.75, 0.9, 0.99}) {
    NormalMap m = bumps;
    for (size_t i = 0; i < m.texels.size(); ++i)
      if (unit_from_hash(hash3(uint32_t(i), 17, uint32_t(fraction * 100))) < fraction) m.texels[i] = atom;
    maps.push_back({std::to_string(int(fraction * 100)) + "% one value", std::move(m)});
  }
  maps.push_back({"two-valued", map_of(side, side, [](uint32_t x, uint32_t row) {
                    return unit_from_hash(hash3(x, row, 3)) < 0.6 ? Vec3f(-0.3f, 0.1f, 1.0f) : Vec3f(0.2f, -0.4f, 1.0f);
                  })});
  maps.push_back({"constant", map_of(side, side, [](uint32_t, uint32_t) { return Vec3f(0.05f, 0.02f, 1.0f); })});
  return maps;
}

}  // namespace mbk::test
