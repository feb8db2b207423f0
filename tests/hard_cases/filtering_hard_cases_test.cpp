// Hard cases of the filtering bakers ([Han07]: `sh` and `vmf` assets), end to end through the asset writer and
// `validate`: constant maps, normals at the horizon, two-valued V-grooves, 1x1 and non-power-of-two maps,
// order-100 SH with normals at the poles. Every value must stay finite and every file must validate.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "formats/asset.h"
#include "formats/validate.h"
#include "libbake/filter/sh_asset.h"
#include "libbake/filter/vmf_asset.h"
#include "tests/filter/filter_test_maps.h"

namespace mbk {
namespace {

NormalMap filled(uint32_t w, uint32_t h, const std::function<Vec3(uint32_t, uint32_t)>& normal) {
  NormalMap m;
  m.width = w, m.height = h;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) m.texels.push_back(normal(x, y).normalized().cast<float>());
  return m;
}

void expect_valid_and_finite(const std::vector<uint8_t>& bytes) {
  for (const Finding& f : validate_asset(bytes)) ADD_FAILURE() << f.id << ": " << f.message;
  const Asset a = Asset::parse(bytes, "hard case");
  for (const SectionInfo& s : a.sections())
    for (float v : a.read_as_float(s.name)) ASSERT_TRUE(std::isfinite(v)) << s.name;
}

void bake_both(const NormalMap& map, int order, int lobes) {
  const LoadedNormalMap input = test::loaded_map(map);
  const ShBakeOptions sh{order, ShPrecision::f16, ShWindow::hann};
  expect_valid_and_finite(sh_asset_writer(input, build_sh_pyramid(map, order, Progress::silent()), sh).serialize());
  for (double align : {0.0, 1.0}) {
    VmfBakeOptions vmf{lobes, {}};
    vmf.em.align = align;
    expect_valid_and_finite(
        vmf_asset_writer(input, nullptr, build_vmf_pyramid(map, nullptr, vmf, Progress::silent()), vmf).serialize());
  }
}

TEST(HardCases, FilteringConstantMap) {
  bake_both(filled(13, 7, [](uint32_t, uint32_t) { return Vec3(0.3, -0.2, 0.9); }), 8, 4);
}

TEST(HardCases, FilteringNormalsAtTheHorizon) {
  bake_both(
      filled(8, 8, [](uint32_t x, uint32_t y) { return Vec3(std::cos(x + 3.0 * y), std::sin(x + 3.0 * y), 0.0); }), 6,
      3);
}

TEST(HardCases, FilteringTwoValuedVGroove) {
  bake_both(filled(10, 6, [](uint32_t x, uint32_t) { return Vec3(x % 2 ? 0.5 : -0.5, 0.0, 0.866); }), 4, 6);
}

TEST(HardCases, FilteringOneByOneAndOneRow) {
  bake_both(filled(1, 1, [](uint32_t, uint32_t) { return Vec3(0, 0, 1); }), 3, 2);
  bake_both(test::random_normal_map(17, 1, 3), 3, 2);
}

TEST(HardCases, FilteringOrder100WithNormalsAtThePoles) {
  bake_both(filled(4, 2, [](uint32_t x, uint32_t) { return x % 2 ? Vec3(0, 0, 1) : Vec3(1e-30, 0, 1); }), 100, 1);
}

}  // namespace
}  // namespace mbk
