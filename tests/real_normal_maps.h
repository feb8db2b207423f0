// The real normal maps beside the repository (MICROBAKE_REAL_DATA_DIR, ../shared/data/real: made by other people,
// never committed), for tests that try the tools as a user would. Height maps (*_height.png) are skipped; maps
// are read as -Y with invalid texels repaired, as most of them are (their SOURCES.md). Tests skip cleanly when
// the folder or its maps are absent.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>

#include "libbake/image/normal_map.h"

namespace mbk::test {

// Calls `use(map, file name)` for every real normal map; returns how many there were.
inline int for_each_real_normal_map(const std::function<void(const NormalMap&, const std::string&)>& use) {
  const std::filesystem::path dir = MICROBAKE_REAL_DATA_DIR;
  if (!std::filesystem::is_directory(dir)) return 0;
  int maps = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".png" || e.path().stem().string().ends_with("_height")) continue;
    const LoadedNormalMap in = load_normal_map(e.path(), {YConvention::minus_y, InvalidTexelPolicy::repair});
    use(in.map, e.path().filename().string());
    ++maps;
  }
  return maps;
}

}  // namespace mbk::test
