// The `sh` and `vmf` assets of a map as the hard-case suite reads them: baked, serialised, validated (every
// finding fails the test) and parsed back, so that every check goes through the bytes a renderer would read.
#pragma once

#include <gtest/gtest.h>

#include "formats/asset.h"
#include "formats/validate.h"
#include "libbake/filter/sh_asset.h"
#include "libbake/filter/vmf_asset.h"
#include "tests/filter/filter_test_maps.h"

namespace mbk::test {

inline Asset parse_valid(const std::vector<uint8_t>& bytes) {
  for (const Finding& f : validate_asset(bytes)) ADD_FAILURE() << f.id << ": " << f.message;
  return Asset::parse(bytes, "hard case");
}

inline Asset bake_sh(const NormalMap& map, int order, ShPrecision precision) {
  const ShBakeOptions options{order, precision, ShWindow::none};
  return parse_valid(bake_sh_asset(loaded_map(map), options, Progress::silent()).serialize());
}

inline Asset bake_vmf(const NormalMap& map, int lobes, double align) {
  VmfBakeOptions options{lobes, {}};
  options.em.align = align;
  return parse_valid(
      vmf_asset_writer(loaded_map(map), nullptr, build_vmf_pyramid(map, nullptr, options, Progress::silent()), options)
          .serialize());
}

}  // namespace mbk::test
