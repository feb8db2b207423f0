// Hard cases of the glints P-NDF ([Wang20]; libbake/glint/glint_pndf.h) on the hardest example for histogram-
// preserving blending: a map 99% one value (the standardization LUT's atom, tests/glint/atom_maps.h), where nearly
// every texel of a footprint reflects the atom's half vector, so pruning cannot skip them. Footprints of one texel
// and of 10^6 texels: the traversal must equal the brute-force sum over every texel, the P-NDF must integrate to 1
// up to its truncation, and the aggregated traversal must stay within its documented bound.
// (A footprint holding no texel centre: GlintPndf.FootprintWithoutTexelCentreIsZeroAndHasNoSample; the LUT's atom
// at every table size: StandardizationLut.AtomIsExactWhateverTheSize and
// KnotsWithinOneStepOfTheExactTransform_AtomMaps; constant and two-valued maps:
// StandardizationLut.ConstantAndTwoValuedChannels.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "formats/lut_layout.h"
#include "libbake/glint/glint_pndf.h"
#include "libbake/glint/glint_technique.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/rmq_table.h"
#include "tests/glint/atom_maps.h"

namespace mbk {
namespace {

struct AtomExample {
  NormalMap map = test::atom_maps(128)[3].map;  // 99% one value
  BakedLut lut = bake_standardization_lut(map, kLutDefaultSize, Progress::silent());
  RmqTable rmq = build_rmq_table(map, 32, 16, Progress::silent());
  RmqTableView view = rmq.view();
  GlintPointQuery point{map, 32, 9, GlintBlendMode::histogram, &lut.tables};
  GlintRangeQuery range{point, view};
  Vec2 atom = Vec2(map.texels[0].x(), map.texels[0].y());
};
const AtomExample& atom_example() {
  static const AtomExample e;
  return e;
}

// Protects against: a footprint that holds exactly one texel centre (sigma 0.1 texel): one element, four
// sub-elements; the normalisation by the footprint's own mass must not divide by a vanishing sum, and D_P must
// integrate to 1 over normals up to the 4 sigma_r truncation (>= 0.995, as for larger footprints).
TEST(HardCases, GlintFootprintOfOneTexel) {
  const AtomExample& e = atom_example();
  const double sigma_r = 0.02;
  const GlintPndf pndf(e.range, sigma_r);
  const GlintFootprint fp{Vec2(3.5, -6.5), 0.1};
  const TexelRange t = footprint_texels(fp);
  ASSERT_EQ(t.t0_lo, t.t0_hi);
  ASSERT_EQ(t.t1_lo, t.t1_hi);
  const RmqBounds box = e.range.element_bounds(t.t0_lo, t.t1_lo);
  const double margin = kGlintNormalCutoffSigmas * sigma_r, step = sigma_r / 8;
  double total = 0.0;
  for (double y = box.min_y - margin; y < box.max_y + margin; y += step)
    for (double x = box.min_x - margin; x < box.max_x + margin; x += step) {
      const Vec2 s(x + step / 2, y + step / 2);
      const double d = pndf.evaluate(fp, s);
      ASSERT_NEAR(d, pndf.evaluate_brute_force(fp, s), 1e-12 * d);
      total += d * step * step;
    }
  EXPECT_LE(total, 1.0 + 1e-4);
  EXPECT_GE(total, 0.995);
}

// Protects against: footprints of 10^6 texels (1000 x 1000, 31 x 31 target patches, far from the origin) on the atom
// map: the traversal splits at every patch border and visits nearly every texel at the atom's normal; it must equal
// the brute force to 1e-5 there and at a bump's normal, and the aggregated traversal must stay within
// 0.03 D + 0.006 / (2 pi sigma^2) of it (glint_pndf.h).
TEST(HardCases, GlintFootprintOfAMillionTexels) {
  const AtomExample& e = atom_example();
  const double sigma_r = 0.01;
  const GlintPndf pndf(e.range, sigma_r);
  const GlintFootprint fp{Vec2(1.0e5 + 0.3, -2.0e5 + 0.7), 1000.0 / (2 * kGlintFootprintCutoffSigmas)};
  const TexelRange t = footprint_texels(fp);
  const double texels = double(t.t0_hi - t.t0_lo + 1) * double(t.t1_hi - t.t1_lo + 1);
  ASSERT_GT(texels, 0.99e6);
  ASSERT_LT(texels, 1.01e6);
  Vec2 bump = e.atom;
  for (const Vec3f& n : e.map.texels)
    if ((Vec2(n.x(), n.y()) - e.atom).norm() > 0.1) bump = Vec2(n.x(), n.y());
  ASSERT_NE(bump, e.atom);
  for (const Vec2& s : {e.atom, bump}) {
    const double brute = pndf.evaluate_brute_force(fp, s);
    ASSERT_GT(brute, 0.0);
    EXPECT_NEAR(pndf.evaluate(fp, s), brute, 1e-5 * brute) << s.transpose();
    const double bound = 0.03 * brute + 0.006 / (2 * std::numbers::pi * sigma_r * sigma_r);
    EXPECT_NEAR(pndf.evaluate(fp, s, nullptr, true), brute, bound) << s.transpose();
  }
}

}  // namespace
}  // namespace mbk
