// The filtering bakers on real normal maps nobody here made (MICROBAKE_REAL_DATA_DIR, see SOURCES.md there;
// skipped when absent): an order-8 SH pyramid of every whole map and a J = 4 vMF fit of a 64 x 64 crop of
// each (the full maps take seconds each: scripts/bench-filtering-bake.sh times them) validate with no
// findings, and the vMF fits stay finite.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "formats/validate.h"
#include "libbake/filter/sh_asset.h"
#include "libbake/filter/vmf_asset.h"
#include "tests/filter/filter_test_maps.h"

namespace mbk {
namespace {

const std::filesystem::path kRealDir = MICROBAKE_REAL_DATA_DIR;

std::vector<std::filesystem::path> real_normal_maps() {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(kRealDir)) return files;
  for (const auto& e : std::filesystem::directory_iterator(kRealDir))
    if (e.path().extension() == ".png" && !e.path().stem().string().ends_with("_height")) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

NormalMap crop(const NormalMap& m, uint32_t size) {
  NormalMap c;
  c.width = std::min(size, m.width), c.height = std::min(size, m.height);
  for (uint32_t y = 0; y < c.height; ++y)
    for (uint32_t x = 0; x < c.width; ++x) c.texels.push_back(m.at(x, y));
  return c;
}

TEST(RealMapsFiltering, ShAndVmfAssetsValidate) {
  const auto files = real_normal_maps();
  if (files.empty()) GTEST_SKIP() << "no real maps in " << kRealDir;
  for (const auto& p : files) {
    const LoadedNormalMap input = load_normal_map(p, {YConvention::plus_y, InvalidTexelPolicy::repair});
    const ShBakeOptions sh{8, ShPrecision::f16, ShWindow::none};
    for (const Finding& f : validate_asset(bake_sh_asset(input, sh, Progress::silent()).serialize()))
      ADD_FAILURE() << p << " sh: " << f.id << ": " << f.message;
    const LoadedNormalMap small = test::loaded_map(crop(input.map, 64));
    const VmfBakeOptions vmf{4, {}};
    const VmfPyramid pyramid = build_vmf_pyramid(small.map, nullptr, vmf, Progress::silent());
    for (const Finding& f : validate_asset(vmf_asset_writer(small, nullptr, pyramid, vmf).serialize()))
      ADD_FAILURE() << p << " vmf: " << f.id << ": " << f.message;
    // EM is slow on real maps (brushed streaks are elongated NDFs that isotropic lobes fit slowly) and may stop at
    // max_iterations, but it must stay finite.
    for (const VmfLevel& level : pyramid.levels) EXPECT_TRUE(std::isfinite(level.statistics.mean_log_likelihood)) << p;
  }
}

}  // namespace
}  // namespace mbk
