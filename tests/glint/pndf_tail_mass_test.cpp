// The P-NDF keeps the microstructure's tail mass (libbake/glint/glint_pndf.h; [Wang20] Eqs. 1-3, [Yan16]
// elements): averaged over many pixel footprints, the normals D_P puts in each band of |s| must be the normals
// the exact microstructure has there. The exact side is the point NDF (glint_pndf.h point_ndf) averaged over
// the footprint: u drawn from the footprint's Gaussian (inside its truncation square, as the P-NDF's texels
// are), s = n(u) + sigma_r N(0, I). The P-NDF side draws from its untruncated elements (GlintPndf::sample_once)
// and counts a draw only when it lies in its element's truncation box, so truncated mass is missing exactly as
// it is from D_P. Both sides use the same
// footprints; the band masses' ratio P-NDF / exact must lie within the tolerance below for every band the exact
// side puts >= 1% of its normals in, for every blend mode, on generated maps with smooth bumps and with flat
// ground cut by scratches (an atom of the standardization), and on the real maps. Before sub-elements (one
// element per texel, linearized on the field's kinks) the scratches kept 0.66-0.71 of the mass in
// [0.05, 0.2) with `none` and overshot 1.2-1.5x beyond |s| = 0.4 on bumps.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "formats/lut_layout.h"
#include "libbake/core/progress.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/glint_pndf.h"
#include "libbake/glint/glint_surface.h"
#include "libbake/glint/glint_technique.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/rmq_table.h"
#include "tests/real_normal_maps.h"

namespace mbk {
namespace {

constexpr std::array<double, 5> kBandEdges = {0.05, 0.1, 0.2, 0.4, 2.0};  // bands of |s|: [edge_i, edge_i+1)
constexpr int kBands = int(kBandEdges.size()) - 1;
constexpr int kFootprints = 2000, kSamplesPerFootprint = 400;
constexpr double kSigmaP = 2.0;  // texels

int band_of(const Vec2& s) {
  const double r = s.norm();
  for (int b = 0; b < kBands; ++b)
    if (r >= kBandEdges[b] && r < kBandEdges[b + 1]) return b;
  return -1;
}

struct BandMasses {
  std::array<double, kBands> pndf{}, exact{};
  double pndf_total = 0.0;  // the fraction of element draws inside their truncation boxes: D_P's integral
};

BandMasses band_masses(const GlintPndf& pndf, const GlintPointQuery& point, double sigma_r, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  const std::function<double()> uniform = [&] { return unit(rng); };
  const double count = double(kFootprints) * kSamplesPerFootprint;
  const double half = kGlintFootprintCutoffSigmas * kSigmaP;
  BandMasses out;
  for (int f = 0; f < kFootprints; ++f) {
    const GlintFootprint fp{Vec2(4096.0 * (2 * unit(rng) - 1), 4096.0 * (2 * unit(rng) - 1)), kSigmaP};
    for (int k = 0; k < kSamplesPerFootprint; ++k) {
      // The P-NDF: one draw of its elements, lost when truncation drops it.
      if (const std::optional<Vec2> s = pndf.sample_once(fp, uniform)) {
        out.pndf_total += 1.0 / count;
        if (const int band = band_of(*s); band >= 0) out.pndf[band] += 1.0 / count;
      }
      // The exact microstructure: a point of the footprint, its normal, the intrinsic roughness.
      Vec2 u;
      do u = fp.center + kSigmaP * Vec2(normal(rng), normal(rng));
      while ((u - fp.center).cwiseAbs().maxCoeff() > half);
      const Vec2 e = point.evaluate(u).n + sigma_r * Vec2(normal(rng), normal(rng));
      if (const int band = band_of(e); band >= 0) out.exact[band] += 1.0 / count;
    }
  }
  return out;
}

// Stated tolerance on the ratio, by the exact band mass m (bands under 1% are printed, not asserted: their
// ratio's standard error passes 1% there): 0.05 where m >= 20%, 0.10 where 5% <= m < 20%, 0.15 where
// 1% <= m < 5%. The goal is 0.05 everywhere; measured worst cases outside it, all in bands of maps with
// texel-wide features whose kinks reach inside the sub-elements: brick_floor's outer band [0.4, 2) 1.06 (none,
// variance; 19.5% of the mass) and 1.12 (linear, 3.3%), scifi_panel_bevels 0.91-0.94 in [0.1, 0.2) (histogram,
// 1.3-1.4%). Histogram blending of maps that are >= 50% one value kept only 0.72-0.83 of the exact mass in the
// bands next to the atom before sub-elements that cross a bend of G^-1 were refined (glint_pndf.h); scratches
// are now within 0.95-1.05 there.
double tolerance(double mass) { return mass >= 0.2 ? 0.05 : mass >= 0.05 ? 0.10 : 0.15; }

// Besides the bands, the mass of [0.05, 0.4) together - the normals between the flat ground and the features,
// where an atom's bend of G^-1 lies - must be within `near_tolerance` of the exact (when it is >= 1%): 0.05 on
// the generated maps; 0.15 on the real maps, where scifi_panel_bevels keeps 0.88 under histogram blending (its
// bevels' transitions still lose mass to the element boxes: 0.97 without truncation).
void expect_tail_mass_kept(const NormalMap& map, const std::string& name, std::initializer_list<double> sigmas,
                           double near_tolerance) {
  constexpr uint32_t kPatch = 32;
  const BakedLut lut = bake_standardization_lut(map, kLutDefaultSize, Progress::silent());
  const RmqTable rmq = build_rmq_table(map, kPatch, 16, Progress::silent());
  const RmqTableView view = rmq.view();
  for (const GlintBlendMode mode :
       {GlintBlendMode::none, GlintBlendMode::linear, GlintBlendMode::variance, GlintBlendMode::histogram}) {
    const GlintPointQuery point(map, kPatch, 5, mode, &lut.tables);
    const GlintRangeQuery range(point, view);
    for (const double sigma_r : sigmas) {
      SCOPED_TRACE(name + ", " + glint_blend_mode_name(mode) + ", sigma_r " + std::to_string(sigma_r));
      const BandMasses m = band_masses(GlintPndf(range, sigma_r), point, sigma_r, 11);
      std::printf("[ info ] %s %-9s sigma_r %.3f: integral %.4f; bands |s| (exact mass, P-NDF / exact):", name.c_str(),
                  glint_blend_mode_name(mode), sigma_r, m.pndf_total);
      for (int b = 0; b < kBands; ++b)
        std::printf(" [%.2f,%.2f) %.4f %.3f", kBandEdges[b], kBandEdges[b + 1], m.exact[b],
                    m.exact[b] > 0 ? m.pndf[b] / m.exact[b] : 0.0);
      std::printf("\n");
      EXPECT_GE(m.pndf_total, 0.98);
      for (int b = 0; b < kBands; ++b)
        if (m.exact[b] >= 0.01) {
          EXPECT_NEAR(m.pndf[b] / m.exact[b], 1.0, tolerance(m.exact[b]))
              << "band " << kBandEdges[b] << " to " << kBandEdges[b + 1];
        }
      double near_exact = 0.0, near_pndf = 0.0;
      for (int b = 0; b < 3; ++b) near_exact += m.exact[b], near_pndf += m.pndf[b];
      if (near_exact >= 0.01) EXPECT_NEAR(near_pndf / near_exact, 1.0, near_tolerance) << "[0.05, 0.4) together";
    }
  }
}

TEST(GlintPndfTailMass, SmoothBumps) {
  expect_tail_mass_kept(generate_normal_map("bumps", {128, 128}, 3, Progress::silent()), "bumps", {0.005, 0.01}, 0.05);
}

TEST(GlintPndfTailMass, FlatGroundCutByScratches) {
  expect_tail_mass_kept(generate_normal_map("scratches", {256, 256}, 1, Progress::silent()), "scratches", {0.005, 0.01},
                        0.05);
}

// The top-left side x side texels (or the whole map when smaller): the real maps are up to 2048^2.
NormalMap top_left(const NormalMap& map, uint32_t side) {
  NormalMap out;
  out.width = std::min(side, map.width);
  out.height = std::min(side, map.height);
  for (uint32_t r = 0; r < out.height; ++r)
    for (uint32_t x = 0; x < out.width; ++x) out.texels.push_back(map.at(x, r));
  return out;
}

TEST(GlintPndfTailMass, RealMaps) {
  const int seen = test::for_each_real_normal_map([](const NormalMap& map, const std::string& name) {
    expect_tail_mass_kept(top_left(map, 256), name, {0.01}, 0.15);
  });
  if (seen == 0) GTEST_SKIP() << "no real normal maps in " << MICROBAKE_REAL_DATA_DIR;
}

}  // namespace
}  // namespace mbk
