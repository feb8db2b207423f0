// A generated normal map as a baker's loaded input (LoadedNormalMap), with a fixed content hash so that the
// histogram bakers' seeds (taken from it) are the same in every test run.
#pragma once

#include <utility>

#include "libbake/image/normal_map.h"

namespace mbk::test {

inline LoadedNormalMap loaded(NormalMap map) {
  LoadedNormalMap in;
  in.map = std::move(map);
  in.record.path = "generated";
  in.record.content_hash = "xxh3:0123456789abcdef";
  return in;
}

}  // namespace mbk::test
