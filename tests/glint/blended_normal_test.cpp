// The point query of the blended microstructure (libbake/glint/blended_normal.h, example_bilinear.h; [Wang20]
// Sec. 4.2, Eqs. 4-6, appendix A.2): the analytic Jacobian against central finite differences for every blend
// mode away from seams and kinks, exact reading of the example (texel centres, clipped border), continuity of
// the smooth blends across target patch borders, determinism, constant examples staying constant, and the
// variance- and histogram-preserving blends keeping the example's mean (and, for histogram, its spread).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "formats/error.h"
#include "formats/lut_layout.h"
#include "libbake/core/progress.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/glint_surface.h"
#include "libbake/glint/blended_normal.h"
#include "libbake/glint/lut_asset.h"

namespace mbk {
namespace {

constexpr std::array<GlintBlendMode, 4> kModes = {GlintBlendMode::none, GlintBlendMode::linear,
                                                  GlintBlendMode::variance, GlintBlendMode::histogram};

struct Fixture {
  NormalMap example = generate_normal_map("bumps", {128, 128}, 4, Progress::silent());
  BakedLut lut = bake_standardization_lut(example, kLutDefaultSize, Progress::silent());
};
const Fixture& fixture() {
  static const Fixture f;
  return f;
}

// Knot interval of x among `keys` (unclamped: below the first knot -1, past the last M - 1, so leaving the
// domain also counts as a change of piece).
int64_t lut_interval(std::span<const float> keys, double x) {
  return int64_t(std::upper_bound(keys.begin(), keys.end(), x, [](double q, float k) { return q < k; }) -
                 keys.begin()) -
         1;
}

// Everything that selects the smooth piece n is evaluated on at u: the target patch (and for `none` the
// nearest vertex), each corner's bilinear cell in the example (unclamped floor of e - 0.5), and for
// `histogram` the LUT interval of G^-1(Z), Z recomputed here from the public pieces (the standardized example,
// read bilinearly).
std::vector<int64_t> piece_signature(const GlintPointQuery& q, const StandardizationLut& lut, const Vec2& u) {
  const TargetPatchLocation loc = q.grid().locate(u);
  std::vector<int64_t> sig = {loc.i, loc.j, loc.local.x() >= 0.5, loc.local.y() >= 0.5};
  double w2 = 0.0;
  std::array<double, 2> z = {0.0, 0.0};
  for (const TargetPatchCorner& c : loc.corners) {
    sig.push_back(int64_t(std::floor(c.example_point.x() - 0.5)));
    sig.push_back(int64_t(std::floor(c.example_point.y() - 0.5)));
    const NormalSample s = sample_example_bilinear(q.blended_channels(), c.example_point);
    w2 += c.weight * c.weight;
    for (int ch = 0; ch < 2; ++ch) z[ch] += c.weight * s.n[ch];
  }
  for (int ch = 0; ch < 2; ++ch) sig.push_back(lut_interval(lut.channels[ch].z(), z[ch] / std::sqrt(w2)));
  return sig;
}

// FD step 1e-5 texels (knots cluster where the example's values do, so a wider stencil crosses one too often): the
// pieces are polynomials in u (bilinear example times bilinear weights), composed with 1/W (smooth, W >= 1/2) and
// piecewise-linear knot tables, so within one piece the central difference is off by h^2/6 |n'''| ~ 1e-11 relative, and
// rounding adds ~eps |n| / h ~ 1e-11: six orders below the 1e-3 bar. "Away from kinks": a point is used only when all
// four stencil points u +/- h e_0, u +/- h e_1 lie on u's piece (same signature). Along an axis-aligned segment the
// texel and patch lines are crossed at most once and the example values I_k are linear, so equal signatures at both
// ends mean no kink in between (Z is smooth; returning to the same knot interval within 2e-5 texels is the only,
// negligible, exception). Every mode uses the same signature, knot intervals included, so all skip the same points,
// mostly for crossing a knot (conservative for the modes without knots).
TEST(GlintPointQuery, JacobianMatchesCentralDifferencesAwayFromKinks_AllModes) {
  const Fixture& f = fixture();
  constexpr double kStep = 1e-5;
  for (const GlintBlendMode mode : kModes) {
    const GlintPointQuery q(f.example, 32, 17, mode, &f.lut.tables);
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> pos(-1000.0, 1000.0);
    int used = 0, rejected = 0;
    double worst = 0.0;
    while (used < 2000) {
      const Vec2 u(pos(rng), pos(rng));
      const std::vector<int64_t> sig = piece_signature(q, f.lut.tables, u);
      bool smooth = true;
      for (const Vec2& d : {Vec2(kStep, 0), Vec2(-kStep, 0), Vec2(0, kStep), Vec2(0, -kStep)})
        smooth = smooth && piece_signature(q, f.lut.tables, u + d) == sig;
      if (!smooth) {
        ++rejected;
        continue;
      }
      ++used;
      const NormalSample s = q.evaluate(u);
      Mat2 fd;
      for (int axis = 0; axis < 2; ++axis) {
        const Vec2 d = kStep * Vec2::Unit(axis);
        fd.col(axis) = (q.evaluate(u + d).n - q.evaluate(u - d).n) / (2 * kStep);
      }
      // Relative to the Jacobian's size, floored at 1e-6 (flat spots of the example: there both are ~0).
      const double rel = (fd - s.jacobian).norm() / std::max(s.jacobian.norm(), 1e-6);
      worst = std::max(worst, rel);
      ASSERT_LE(rel, 1e-3) << glint_blend_mode_name(mode) << " at u = " << u.transpose() << "\nJ =\n"
                           << s.jacobian << "\nFD =\n"
                           << fd;
    }
    EXPECT_LT(rejected, used) << glint_blend_mode_name(mode) << ": too many points near kinks";
    std::printf("[ info ] %s: %d points, %d near kinks skipped, worst relative error %.3g\n",
                glint_blend_mode_name(mode), used, rejected, worst);
  }
}

TEST(GlintPointQuery, ExampleReadingIsExactAtTexelCentresAndClippedAtTheBorder) {
  const NormalMap& map = fixture().example;
  const ExampleChannels ex = normal_components(map);
  for (uint32_t r : {0u, 5u, 127u})
    for (uint32_t x : {0u, 64u, 127u}) {
      const NormalSample s = sample_example_bilinear(ex, Vec2(x + 0.5, r + 0.5));
      EXPECT_EQ(s.n.x(), double(map.at(x, r).x()));
      EXPECT_EQ(s.n.y(), double(map.at(x, r).y()));
    }
  // Within half a texel of (and beyond) the left border the value is the first column's and d/de_0 is 0.
  for (double e0 : {0.0, 0.25, 0.4999}) {
    const NormalSample s = sample_example_bilinear(ex, Vec2(e0, 40.5));
    EXPECT_EQ(s.n.x(), double(map.at(0, 40).x()));
    EXPECT_EQ(s.jacobian(0, 0), 0.0);
    EXPECT_EQ(s.jacobian(1, 0), 0.0);
  }
  // Midway between two centres: the mean of the two texels.
  const NormalSample mid = sample_example_bilinear(ex, Vec2(11.0, 20.5));
  EXPECT_NEAR(mid.n.x(), 0.5 * (double(map.at(10, 20).x()) + double(map.at(11, 20).x())), 1e-15);
}

TEST(GlintPointQuery, SmoothBlendsAreContinuousAcrossTargetPatchBorders) {
  const Fixture& f = fixture();
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> along(-300.0, 300.0);
  std::uniform_int_distribution<int> line(-20, 20);
  for (const GlintBlendMode mode : {GlintBlendMode::linear, GlintBlendMode::variance, GlintBlendMode::histogram}) {
    const GlintPointQuery q(f.example, 32, 5, mode, &f.lut.tables);
    for (int n = 0; n < 2000; ++n) {
      const double border = line(rng) * q.grid().target_side();  // a vertical patch border u_0 = i h
      const double y = along(rng);
      const NormalSample left = q.evaluate(Vec2(border - 1e-9, y)), right = q.evaluate(Vec2(border, y));
      // The corners that leave have weight 0 on the border; 1e-9 texels at slopes of O(1) moves n by ~1e-9.
      EXPECT_NEAR((left.n - right.n).norm(), 0.0, 1e-7) << glint_blend_mode_name(mode) << " y = " << y;
    }
  }
}

TEST(GlintPointQuery, SameSeedSameValuesOtherSeedOtherValues) {
  const Fixture& f = fixture();
  for (const GlintBlendMode mode : kModes) {
    const GlintPointQuery a(f.example, 32, 99, mode, &f.lut.tables), b(f.example, 32, 99, mode, &f.lut.tables);
    const GlintPointQuery c(f.example, 32, 100, mode, &f.lut.tables);
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> pos(-1e4, 1e4);
    int differ = 0;
    for (int n = 0; n < 1000; ++n) {
      const Vec2 u(pos(rng), pos(rng));
      const NormalSample sa = a.evaluate(u), sb = b.evaluate(u);
      ASSERT_EQ(sa.n, sb.n);
      ASSERT_EQ(sa.jacobian, sb.jacobian);
      differ += c.evaluate(u).n != sa.n;
    }
    EXPECT_GT(differ, 900) << glint_blend_mode_name(mode);
  }
}

TEST(GlintPointQuery, ConstantExampleGivesThatConstantWithZeroJacobian_AllModes) {
  NormalMap flat{40, 30, std::vector<Vec3f>(40 * 30, Vec3f(0.3f, -0.2f, 0.9327379f))};
  const BakedLut lut = bake_standardization_lut(flat, 64, Progress::silent());
  for (const GlintBlendMode mode : kModes) {
    const GlintPointQuery q(flat, 16, 1, mode, &lut.tables);
    std::mt19937_64 rng(24);
    std::uniform_real_distribution<double> pos(-500.0, 500.0);
    for (int n = 0; n < 2000; ++n) {
      const NormalSample s = q.evaluate(Vec2(pos(rng), pos(rng)));
      EXPECT_NEAR(s.n.x(), double(0.3f), 1e-12) << glint_blend_mode_name(mode);
      EXPECT_NEAR(s.n.y(), double(-0.2f), 1e-12) << glint_blend_mode_name(mode);
      EXPECT_LE(s.jacobian.cwiseAbs().maxCoeff(), 1e-12) << glint_blend_mode_name(mode);
    }
  }
}

// The blends keep the statistics of the example AS THEY READ IT: patch origins are uniform in [0, W - P]^2, so
// texels near the border are read less often than central ones; on this bumps example that alone moves the
// blended mean by up to 0.05 example standard deviations from the whole example's mean (seen while writing this
// test; the variance blend amplifies it by E[1/W]). The references are therefore computed here independently
// of the blend code, from R(d), the mean of the bilinear example at o + d over all origins o, and from the read
// distribution I(o + d) over all origins o and offsets d. With 10^5 random points in [-4096, 4096]^2 (~2.6e5
// target patches of side 16: nearly independent patch draws):
// - linear and variance: the exact expectation E[n] = m + sum_k E_u[w_k / W (R(d_k) - m)] (m = 0 and W = 1 for
//   linear; E_u over one target patch by a 32 x 32 midpoint rule), within 4 standard errors.
// - histogram: Eq. 6 has no closed-form expectation. Its mean must match the variance blend's expectation (the
//   same patches and weights; G is monotone and near-affine on this example) within 0.02 read standard
//   deviations, and its standard deviation the read distribution's within 3% (the variance blend alone, with
//   no G round trip, keeps only the second moment of a Gaussian: this is the histogram's job).
TEST(GlintPointQuery, BlendsKeepTheStatisticsOfTheExampleAsRead) {
  const Fixture& f = fixture();
  constexpr uint32_t kPatch = 32;
  constexpr int kQuad = 32;
  const uint32_t origins = f.example.width - kPatch + 1;
  // R(d) on the 2 kQuad x 2 kQuad midpoint grid of offsets d in [0, P]^2 (the four corners' offsets of the
  // kQuad x kQuad quadrature points below), and the moments of the read distribution I(o + d) over all o and d.
  const ExampleChannels example = normal_components(f.example);
  std::vector<Vec2> table(4 * kQuad * kQuad);
  Vec2 read_sum = Vec2::Zero(), read_sq = Vec2::Zero();
  for (int b = 0; b < 2 * kQuad; ++b)
    for (int a = 0; a < 2 * kQuad; ++a) {
      const Vec2 d((a + 0.5) * kPatch / (2.0 * kQuad), (b + 0.5) * kPatch / (2.0 * kQuad));
      Vec2 sum = Vec2::Zero();
      for (uint32_t oy = 0; oy < origins; ++oy)
        for (uint32_t ox = 0; ox < origins; ++ox) {
          const Vec2 v = sample_example_bilinear(example, Vec2(ox, oy) + d).n;
          sum += v;
          read_sq += v.cwiseProduct(v);
        }
      read_sum += sum;
      table[b * 2 * kQuad + a] = sum / double(origins * origins);
    }
  const double read_count = double(table.size()) * origins * origins;
  const Vec2 read_m = read_sum / read_count;
  const Vec2 read_sd = (read_sq / read_count - read_m.cwiseProduct(read_m)).cwiseSqrt();
  Vec2 variance_expected = Vec2::Zero();

  for (const GlintBlendMode mode : {GlintBlendMode::linear, GlintBlendMode::variance, GlintBlendMode::histogram}) {
    const GlintPointQuery q(f.example, kPatch, 31, mode, &f.lut.tables);
    std::mt19937_64 rng(25);
    std::uniform_real_distribution<double> pos(-4096.0, 4096.0);
    constexpr int kPoints = 100000;
    Vec2 m = Vec2::Zero(), s2 = Vec2::Zero();
    for (int n = 0; n < kPoints; ++n) {
      const Vec2 v = q.evaluate(Vec2(pos(rng), pos(rng))).n;
      m += v;
      s2 += v.cwiseProduct(v);
    }
    m /= kPoints;
    const Vec2 s = (s2 / kPoints - m.cwiseProduct(m)).cwiseSqrt();
    if (mode == GlintBlendMode::histogram) {
      for (int ch = 0; ch < 2; ++ch) {
        std::printf(
            "[ info ] histogram channel %d: mean %.5f (variance blend's expectation %.5f, read %.5f), sd %.5f "
            "(read %.5f)\n",
            ch, m[ch], variance_expected[ch], read_m[ch], s[ch], read_sd[ch]);
        EXPECT_NEAR(m[ch], variance_expected[ch], 0.02 * read_sd[ch]) << "channel " << ch;
        EXPECT_NEAR(s[ch], read_sd[ch], 0.03 * read_sd[ch]) << "channel " << ch;
      }
      continue;
    }
    const Vec2 mean = mode == GlintBlendMode::variance ? q.example_mean() : Vec2::Zero();
    Vec2 expected = Vec2::Zero();
    for (int a = 0; a < kQuad; ++a)
      for (int b = 0; b < kQuad; ++b) {
        const Vec2 fl((a + 0.5) / kQuad, (b + 0.5) / kQuad);
        std::array<double, 4> w;
        double w2 = 0.0;
        for (int k = 0; k < 4; ++k) {
          w[k] = (k & 1 ? fl.x() : 1 - fl.x()) * (k >> 1 ? fl.y() : 1 - fl.y());
          w2 += w[k] * w[k];
        }
        const double W = mode == GlintBlendMode::variance ? std::sqrt(w2) : 1.0;
        for (int k = 0; k < 4; ++k) {
          // Offset d_k = (f + 1 - (dx, dy)) h: grid cell (a + kQuad (1 - dx), b + kQuad (1 - dy)).
          const int ga = a + kQuad * (1 - (k & 1)), gb = b + kQuad * (1 - (k >> 1));
          expected += w[k] / W * (table[gb * 2 * kQuad + ga] - mean);
        }
      }
    expected = mean + expected / double(kQuad * kQuad);
    if (mode == GlintBlendMode::variance) variance_expected = expected;
    for (int ch = 0; ch < 2; ++ch) {
      const double standard_error = s[ch] / std::sqrt(double(kPoints));
      std::printf("[ info ] %s channel %d: mean %.5f, expected %.5f, standard error %.5f\n",
                  glint_blend_mode_name(mode), ch, m[ch], expected[ch], standard_error);
      EXPECT_NEAR(m[ch], expected[ch], 4 * standard_error) << glint_blend_mode_name(mode) << " channel " << ch;
    }
  }
}

TEST(GlintPointQuery, RejectsMissingLutAndBadPatchSide) {
  const NormalMap& ex = fixture().example;
  EXPECT_THROW(GlintPointQuery(ex, 32, 0, GlintBlendMode::histogram, nullptr), Error);
  EXPECT_THROW(GlintPointQuery(ex, 129, 0, GlintBlendMode::linear), Error);
  EXPECT_NO_THROW(GlintPointQuery(ex, 128, 0, GlintBlendMode::linear));
}

}  // namespace
}  // namespace mbk
