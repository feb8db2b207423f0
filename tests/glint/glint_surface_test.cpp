// A glint material assembled from its example and its serialized assets (libbake/glint/glint_surface.h): read
// back through formats/ only, it answers exactly what the in-memory tables answer, its reference equals its
// traversal, and wrong assets, sizes, names and settings are refused with a clear error.
#include <gtest/gtest.h>

#include <random>

#include "formats/error.h"
#include "formats/lut_layout.h"
#include "libbake/core/progress.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/glint_surface.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/rmq_asset.h"
#include "libbake/glint/rmq_table.h"

namespace mbk {
namespace {

struct Baked {
  LoadedNormalMap input;
  BakedLut lut;
  Asset lut_asset() const { return Asset::parse(lut_asset_writer(lut, input.record).serialize(), "lut.mbk"); }
  Asset rmq_asset(uint32_t patch) const {
    return Asset::parse(bake_rmq_asset(input, patch, 16, Progress::silent()).serialize(), "rmq.mbk");
  }
};
Baked baked(uint32_t side) {
  Baked b;
  b.input.map = generate_normal_map("leather", {side, side}, 4, Progress::silent());
  b.input.record.path = "leather.exr";
  b.input.record.width = b.input.record.height = side;
  b.lut = bake_standardization_lut(b.input.map, kLutDefaultSize, Progress::silent());
  return b;
}

TEST(GlintSurface, AssetsReadBackAnswerLikeTheInMemoryTables) {
  const Baked b = baked(96);
  const GlintSettings settings{GlintBlendMode::histogram, 0.01, 32, 5};
  const auto surface = GlintSurface::open(b.input.map, b.lut_asset(), b.rmq_asset(32), settings);
  const RmqTable table = build_rmq_table(b.input.map, 32, 16, Progress::silent());
  const RmqTableView view = table.view();
  const GlintPointQuery q(b.input.map, 32, 5, GlintBlendMode::histogram, &b.lut.tables);
  const GlintRangeQuery r(q, view);
  const GlintPndf pndf(r, 0.01);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> pos(-300.0, 300.0), unit(0.0, 1.0);
  for (int n = 0; n < 200; ++n) {
    const GlintFootprint fp{Vec2(pos(rng), pos(rng)), 0.5 + 4 * unit(rng)};
    const Vec2 s = q.evaluate(fp.center).n + Vec2(0.02 * unit(rng), 0.02 * unit(rng));
    const double expected = pndf.evaluate(fp, s);
    EXPECT_EQ(surface->pndf().evaluate(fp, s), expected);
    EXPECT_NEAR(surface->pndf().evaluate_brute_force(fp, s), expected, 1e-5 * expected);
  }
}

TEST(GlintSurface, WrongAssetsSizesNamesAndSettingsAreRefused) {
  const Baked b = baked(64);
  const Baked other = baked(96);
  const GlintSettings ok{GlintBlendMode::linear, 0.01, 32, 1};
  EXPECT_THROW(GlintSurface::open(b.input.map, b.lut_asset(), other.rmq_asset(32), ok), Error);  // size
  EXPECT_THROW(GlintSurface::open(b.input.map, b.rmq_asset(32), b.rmq_asset(32), ok), Error);    // kind
  EXPECT_THROW(GlintSurface::open(b.input.map, b.lut_asset(), b.lut_asset(), ok), Error);        // kind
  EXPECT_THROW(GlintSurface::open(b.input.map, b.lut_asset(), b.rmq_asset(32), {GlintBlendMode::linear, 0.01, 31, 1}),
               Error);  // odd patch
  EXPECT_THROW(GlintSurface::open(b.input.map, b.lut_asset(), b.rmq_asset(32), {GlintBlendMode::linear, 0.0, 32, 1}),
               Error);  // roughness
  EXPECT_THROW(parse_glint_blend_mode("histo", "scene.json: materials.m.glints.blending"), Error);
  EXPECT_EQ(parse_glint_blend_mode("variance", "x"), GlintBlendMode::variance);
}

}  // namespace
}  // namespace mbk
