// vMF mixture MIP maps (libbake/filter/vmf_pyramid.h) and their asset (vmf_asset.h, formats/kind_vmf.cpp):
// constant maps and V-grooves at every level, coherent slots, features, determinism across thread counts, and
// bakes of odd sizes that pass validate with no findings.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "formats/asset.h"
#include "formats/validate.h"
#include "libbake/core/parallel.h"
#include "libbake/filter/vmf_asset.h"
#include "libbake/filter/vmf_pyramid.h"
#include "libbake/gen/generator.h"
#include "tests/filter/filter_test_maps.h"

namespace mbk {
namespace {

Vec3 tilted(double degrees_about_y) {
  const double a = degrees_about_y * std::numbers::pi / 180;
  return Vec3(std::sin(a), 0, std::cos(a));
}

// Columns alternate between two facets of a V-groove (+-30 degrees about y).
NormalMap v_groove(uint32_t w, uint32_t h) {
  NormalMap m;
  m.width = w, m.height = h;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) m.texels.push_back(tilted(x % 2 ? 30 : -30).cast<float>());
  return m;
}

std::vector<VmfComponent> texel_lobes(const VmfLevel& level, uint32_t x, uint32_t y, int J) {
  std::vector<VmfComponent> out;
  for (int j = 0; j < J; ++j)
    out.push_back(decode_lobe(&level.lobes[((size_t(y) * level.width + x) * J + j) * 4], kVmfKappaMax));
  return out;
}

TEST(VmfPyramid, ConstantMapOneLobeAtKappaCapNoNaN) {
  NormalMap m;
  m.width = 9, m.height = 6;
  m.texels.assign(54, tilted(25).cast<float>());
  const VmfPyramid p = build_vmf_pyramid(m, nullptr, VmfBakeOptions{4, {}}, Progress::silent());
  ASSERT_EQ(p.levels.size(), 4u);
  for (const VmfLevel& level : p.levels) {
    for (float v : level.lobes) ASSERT_TRUE(std::isfinite(v));
    for (uint32_t y = 0; y < level.height; ++y)
      for (uint32_t x = 0; x < level.width; ++x) {
        const auto lobes = texel_lobes(level, x, y, 4);
        EXPECT_NEAR(lobes[0].alpha, 1.0, 1e-7);
        EXPECT_EQ(lobes[0].kappa, kVmfKappaMax);
        EXPECT_LT((lobes[0].mu - tilted(25)).norm(), 1e-6);
        for (int j = 1; j < 4; ++j) EXPECT_EQ(lobes[size_t(j)].alpha, 0.0);
      }
  }
}

TEST(VmfPyramid, VGrooveGivesTwoLobesAtTheFacets) {
  for (int J : {2, 4}) {
    const VmfPyramid p = build_vmf_pyramid(v_groove(16, 8), nullptr, VmfBakeOptions{J, {}}, Progress::silent());
    for (size_t k = 1; k < p.levels.size(); ++k) {
      const auto lobes = texel_lobes(p.levels[k], 0, 0, J);
      int live = 0;
      for (const auto& c : lobes) {
        if (c.alpha <= 0) continue;
        ++live;
        EXPECT_NEAR(c.alpha, 0.5, 1e-6);
        EXPECT_EQ(c.kappa, kVmfKappaMax);
        EXPECT_LT(std::min((c.mu - tilted(30)).norm(), (c.mu - tilted(-30)).norm()), 1e-6);
      }
      EXPECT_EQ(live, 2) << "J " << J << " level " << k;
    }
  }
}

// The coherence pass puts the same facet in the same slot in every texel of a level, and in the parent.
TEST(VmfPyramid, CoherentSlotsAcrossTexelsAndLevels) {
  const VmfPyramid p = build_vmf_pyramid(v_groove(16, 16), nullptr, VmfBakeOptions{3, {}}, Progress::silent());
  const Vec3 top0 = texel_lobes(p.levels.back(), 0, 0, 3)[0].mu;
  for (size_t k = 1; k < p.levels.size(); ++k)
    for (uint32_t y = 0; y < p.levels[k].height; ++y)
      for (uint32_t x = 0; x < p.levels[k].width; ++x)
        EXPECT_LT((texel_lobes(p.levels[k], x, y, 3)[0].mu - top0).norm(), 1e-6);
}

TEST(VmfPyramid, SameBytesWhateverTheThreadCount) {
  const LoadedNormalMap input = test::loaded_map(test::random_normal_map(21, 13, 4));
  VmfBakeOptions options{3, {}};
  options.em.align = 0.3;
  set_thread_count(1);
  const auto one =
      vmf_asset_writer(input, nullptr, build_vmf_pyramid(input.map, nullptr, options, Progress::silent()), options)
          .serialize();
  set_thread_count(2);
  const auto two =
      vmf_asset_writer(input, nullptr, build_vmf_pyramid(input.map, nullptr, options, Progress::silent()), options)
          .serialize();
  set_thread_count(0);
  EXPECT_EQ(one, two);
}

// A map large enough for every path: texels in parallel, chunked coarse texels, the top texel's E-step split.
TEST(VmfPyramid, SameBytesWhateverTheThreadCountWithChunks) {
  const LoadedNormalMap input =
      test::loaded_map(generate_normal_map("leather", MapSize{256, 256}, 3, Progress::silent()));
  const VmfBakeOptions options;
  std::vector<std::vector<uint8_t>> bytes;
  for (int threads : {1, 2}) {
    set_thread_count(threads);
    bytes.push_back(
        vmf_asset_writer(input, nullptr, build_vmf_pyramid(input.map, nullptr, options, Progress::silent()), options)
            .serialize());
  }
  set_thread_count(0);
  EXPECT_EQ(bytes[0], bytes[1]);
}

TEST(VmfPyramid, MaterialFeaturesFollowTheirFacet) {
  const NormalMap m = v_groove(8, 8);
  Image colour{8, 8, 3, {}};
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 8; ++x)
      for (float c : {x % 2 ? 1.0f : 0.0f, 0.5f, x % 2 ? 0.0f : 1.0f}) colour.pixels.push_back(c);
  const VmfPyramid p = build_vmf_pyramid(m, &colour, VmfBakeOptions{2, {}}, Progress::silent());
  ASSERT_EQ(p.feature_count, 3);
  const VmfLevel& top = p.levels.back();
  const auto lobes = texel_lobes(top, 0, 0, 2);
  for (int j = 0; j < 2; ++j) {
    const float* y = &top.features[size_t(j) * 3];
    const double red = lobes[size_t(j)].mu.x() > 0 ? 1.0 : 0.0;  // +30 degrees (x > 0) is the odd columns
    EXPECT_NEAR(y[0] / lobes[size_t(j)].alpha, red, 1e-6);
    EXPECT_NEAR(y[1] / lobes[size_t(j)].alpha, 0.5, 1e-6);
    EXPECT_NEAR(y[2] / lobes[size_t(j)].alpha, 1.0 - red, 1e-6);
  }
  Image wrong{7, 8, 3, std::vector<float>(7 * 8 * 3, 0.0f)};
  EXPECT_THROW(build_vmf_pyramid(m, &wrong, VmfBakeOptions{2, {}}, Progress::silent()), Error);
}

struct VmfAssetCase {
  uint32_t w, h;
  int lobes;
  double align;
  bool features;
};
class VmfAssetCases : public ::testing::TestWithParam<VmfAssetCase> {};

TEST_P(VmfAssetCases, PassesValidationWithNoFindings) {
  const VmfAssetCase c = GetParam();
  const LoadedNormalMap input = test::loaded_map(test::random_normal_map(c.w, c.h, c.w * 7 + c.h));
  Image colour{c.w, c.h, 2, std::vector<float>(size_t(c.w) * c.h * 2)};
  for (size_t i = 0; i < colour.pixels.size(); ++i) colour.pixels[i] = float((i * 37) % 11) / 10.0f;
  VmfBakeOptions options{c.lobes, {}};
  options.em.align = c.align;
  const VmfPyramid p = build_vmf_pyramid(input.map, c.features ? &colour : nullptr, options, Progress::silent());
  const nlohmann::json material = {{"path", "colour.png"}};
  const auto bytes = vmf_asset_writer(input, c.features ? &material : nullptr, p, options).serialize();
  for (const Finding& f : validate_asset(bytes)) ADD_FAILURE() << f.id << ": " << f.message;
  const Asset a = Asset::parse(bytes, "vmf");
  EXPECT_EQ(a.metadata()["parameters"]["lobes"], c.lobes);
  EXPECT_EQ(a.read<float>("level_0").size(), size_t(c.w) * c.h * c.lobes * 4);
}

INSTANTIATE_TEST_SUITE_P(SizesLobesAlignFeatures, VmfAssetCases,
                         ::testing::Values(VmfAssetCase{16, 16, 4, 0.0, false}, VmfAssetCase{7, 5, 2, 0.0, true},
                                           VmfAssetCase{1, 1, 3, 0.0, false}, VmfAssetCase{11, 3, 6, 0.5, true},
                                           VmfAssetCase{1, 9, 1, 0.0, false}));

}  // namespace
}  // namespace mbk
