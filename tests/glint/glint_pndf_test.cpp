// The P-NDF of the blended microstructure (libbake/glint/glint_pndf.h, position_normal_element.h; [Wang20]
// Eqs. 1-3, Alg. 3, Sec. 5.2-5.3): the traversal equals the brute-force sum over every texel of the footprint
// to 1e-5 relative on >= 1,000 random queries (footprints 1 to 256 texels wide, up to 17 target patches per
// axis, every blend mode, 16 and 8 bits, far and negative positions); the element's closed form equals
// numerical quadrature; D_P integrates to 1 over normals up to the documented truncation; a histogram of
// >= 10^6 samples matches the evaluated P-NDF (relative L1 <= 2%); empty footprints and bad parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "formats/error.h"
#include "formats/lut_layout.h"
#include "libbake/core/progress.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/glint_pndf.h"
#include "libbake/glint/glint_surface.h"
#include "libbake/glint/glint_technique.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/rmq_table.h"

namespace mbk {
namespace {

constexpr std::array<GlintBlendMode, 4> kModes = {GlintBlendMode::none, GlintBlendMode::linear,
                                                  GlintBlendMode::variance, GlintBlendMode::histogram};

struct Fixture {
  NormalMap example = generate_normal_map("bumps", {128, 128}, 3, Progress::silent());
  BakedLut lut = bake_standardization_lut(example, kLutDefaultSize, Progress::silent());
  RmqTable rmq16 = build_rmq_table(example, 32, 16, Progress::silent());
  RmqTable rmq8 = build_rmq_table(example, 32, 8, Progress::silent());
};
const Fixture& fixture() {
  static const Fixture f;
  return f;
}

// A pixel's half-vector slope field (glint_pndf.h, "The half vector's slope field"): K = ds/du sweeping s by up to
// 10 sigma_r along a random direction of s across a footprint `width` texels wide and by up to sigma_r across it,
// as at grazing angles; one in four singular (rank 1: s moves along one line), one in eight huge (100x).
Mat2 random_slope(std::mt19937_64& rng, double sigma_r, double width) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto direction = [&] {
    const double angle = 2 * std::numbers::pi * unit(rng);
    return Vec2(std::cos(angle), std::sin(angle));
  };
  const Vec2 a = direction(), b = direction(), w(-a.y(), a.x());
  const double along = 10 * sigma_r * unit(rng) / width, across = unit(rng) < 0.25 ? 0.0 : sigma_r * unit(rng) / width;
  const Mat2 k = along * a * b.transpose() + across * w * Vec2(-b.y(), b.x()).transpose();
  return unit(rng) < 0.125 ? Mat2(100.0 * k) : k;
}

// A query: a footprint and a normal s near the normals it holds (the point query at a random point of the
// footprint, moved by up to a few sigma_r), so that most answers are not 0.
struct Query {
  GlintFootprint footprint;
  Vec2 s;
};
Query random_query(const GlintPointQuery& q, std::mt19937_64& rng, double sigma_r, double width) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double far = unit(rng) < 0.2 ? 1.0e6 : 500.0;  // some footprints far from the origin
  Query out;
  out.footprint.center = Vec2((2 * unit(rng) - 1) * far, (2 * unit(rng) - 1) * far);
  out.footprint.sigma = width / (2 * kGlintFootprintCutoffSigmas);
  const Vec2 inside = out.footprint.center + width * Vec2(unit(rng) - 0.5, unit(rng) - 0.5);
  out.s = q.evaluate(inside).n + 3 * sigma_r * Vec2(2 * unit(rng) - 1, 2 * unit(rng) - 1);
  if (unit(rng) < 0.4) out.footprint.slope = random_slope(rng, sigma_r, width);
  return out;
}

// The peak of the elements' normal Gaussian, 1 / (2 pi sigma_r^2).
double normal_peak(double sigma_r) { return 1.0 / (2.0 * std::numbers::pi * sigma_r * sigma_r); }

TEST(GlintPndf, TraversalEqualsBruteForce_1000Queries_Footprints1To256_AllModes) {
  const Fixture& f = fixture();
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> log_width(0.0, std::log(256.0));
  int nonzero = 0, queries = 0;
  uint64_t nodes = 0, texels = 0;
  for (const RmqTable* table : {&f.rmq16, &f.rmq8}) {
    const RmqTableView view = table->view();
    for (const GlintBlendMode mode : kModes) {
      const GlintPointQuery q(f.example, 32, 9, mode, &f.lut.tables);
      const GlintRangeQuery r(q, view);
      for (const double sigma_r : {0.005, 0.01, 0.05}) {
        const GlintPndf pndf(r, sigma_r);
        for (int n = 0; n < 42; ++n, ++queries) {
          const double width = std::exp(log_width(rng));  // 1 .. 256 texels, log-uniform
          const Query qq = random_query(q, rng, sigma_r, width);
          PndfStatistics stats;
          const double traversal = pndf.evaluate(qq.footprint, qq.s, &stats);
          const double brute = pndf.evaluate_brute_force(qq.footprint, qq.s);
          const TexelRange t = footprint_texels(qq.footprint);
          nodes += stats.nodes_visited;
          texels += uint64_t((t.t0_hi - t.t0_lo + 1) * (t.t1_hi - t.t1_lo + 1));
          if (brute == 0.0) {
            ASSERT_EQ(traversal, 0.0);
            continue;
          }
          ++nonzero;
          ASSERT_LE(std::abs(traversal - brute), 1e-5 * brute)
              << "width " << width << " sigma_r " << sigma_r << " bits " << view.layout().bits;
        }
      }
    }
  }
  EXPECT_GE(queries, 1000);
  EXPECT_GE(nonzero, queries / 2) << "too many queries answered 0 to test much";
  std::printf("[ info ] %d queries, %d non-zero; %llu nodes visited for %llu footprint texels\n", queries, nonzero,
              (unsigned long long)nodes, (unsigned long long)texels);
}

// Eq. (1) of position_normal_element.h against a midpoint rule over u (step 0.02 texels over +/- 8 sigma of
// the footprint-element product, which is far narrower than the grid).
TEST(GlintPndf, ElementIntegralMatchesNumericalQuadrature) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> v(-1.0, 1.0);
  for (int n = 0; n < 20; ++n) {
    PositionNormalElement e;
    e.sigma_h = n % 2 ? kGlintElementSigmaTexels : kGlintSubElementSigmaTexels;
    e.center = Vec2(10 + v(rng), -3 + v(rng));
    e.n = Vec2(0.3 * v(rng), 0.3 * v(rng));
    e.jacobian << 0.05 * v(rng), 0.05 * v(rng), 0.05 * v(rng), 0.05 * v(rng);
    const GlintFootprint fp{Vec2(10 + 2 * v(rng), -3 + 2 * v(rng)), 0.5 + std::abs(v(rng))};
    const double sigma_r = 0.02;
    const Vec2 s = e.n + Vec2(0.02 * v(rng), 0.02 * v(rng));
    const double sh = e.sigma_h;
    double sum = 0.0;
    constexpr double kStep = 0.02;
    for (double y = e.center.y() - 8 * sh; y < e.center.y() + 8 * sh; y += kStep)
      for (double x = e.center.x() - 8 * sh; x < e.center.x() + 8 * sh; x += kStep) {
        const Vec2 u(x + kStep / 2, y + kStep / 2);
        const Vec2 r = s - e.n - e.jacobian * (u - e.center);
        sum += std::exp(-(u - fp.center).squaredNorm() / (2 * fp.sigma * fp.sigma) -
                        (u - e.center).squaredNorm() / (2 * sh * sh) - r.squaredNorm() / (2 * sigma_r * sigma_r));
      }
    sum *= kStep * kStep;
    const double closed = element_footprint_integral(e, fp, sigma_r, s);
    EXPECT_NEAR(closed, sum, 1e-6 * std::max(sum, 1e-12)) << "element " << n;
  }
}

// The hard case exact standardization creates: next to an atom G is steep, so one row of an element's Jacobian can
// be ~1e11 (measured on a bumpy map with a 4096 grid). Eq. (1) must stay finite and positive there (the textbook
// det A = A00 A11 - A01^2 came out 0 or negative: NaN pixels), and follow its asymptote: once the huge row
// dominates A, scaling it by t scales det A by t^2 and leaves the exponent's limit, so k t tends to a constant.
// The exponent e - b A^-1 b still cancels as t grows: k t moves by 4e-6 relative from 1e10 to 1e12 and by 2.5e-3
// to 1e14, far beyond any Jacobian a float map can produce at the default grid.
TEST(GlintPndf, ElementIntegralStaysFiniteForHugeJacobians) {
  PositionNormalElement e;
  e.sigma_h = kGlintSubElementSigmaTexels;
  e.center = Vec2(3.2, -1.1);
  e.n = Vec2(0.05, -0.02);
  const GlintFootprint fp{Vec2(3.0, -1.0), 1.3};
  const Vec2 s = e.n + Vec2(0.01, 0.004);
  double previous = 0.0;
  for (double t : {1e6, 1e8, 1e10, 1e12, 1e14}) {
    e.jacobian << -0.18, -0.47, -1.45 * t, -0.498 * t;
    const double k = element_footprint_integral(e, fp, 0.01, s);
    ASSERT_TRUE(std::isfinite(k) && k > 0.0) << t << ": " << k;
    if (previous > 0.0) {
      EXPECT_NEAR(k * t, previous, (t < 1e13 ? 1e-5 : 1e-2) * previous) << t;
    }
    previous = k * t;
  }
}

// The aggregated traversal (glint_pndf.h, "Aggregation") against brute force on >= 1,000 random queries per map,
// within the stated bound |D_agg - D| <= 0.03 D + 0.006 / (2 pi sigma_r^2): maps of smooth bumps and of flat
// ground cut by scratches (where aggregation pays), every blend mode, footprints 1 to 256 texels wide, 40% of
// them with a slope field.
TEST(GlintPndf, AggregatedTraversalWithinItsBound_1000Queries) {
  const NormalMap scratches = generate_normal_map("scratches", {128, 128}, 2, Progress::silent());
  const BakedLut scratches_lut = bake_standardization_lut(scratches, kLutDefaultSize, Progress::silent());
  const RmqTable scratches_rmq = build_rmq_table(scratches, 32, 16, Progress::silent());
  const Fixture& f = fixture();
  struct Map {
    const NormalMap* example;
    const BakedLut* lut;
    const RmqTable* rmq;
  };
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  uint64_t aggregated = 0;
  for (const Map& m : {Map{&f.example, &f.lut, &f.rmq16}, Map{&scratches, &scratches_lut, &scratches_rmq}}) {
    const RmqTableView view = m.rmq->view();
    for (const GlintBlendMode mode : kModes) {
      const GlintPointQuery q(*m.example, 32, 3, mode, &m.lut->tables);
      const GlintRangeQuery r(q, view);
      for (int n = 0; n < 130; ++n) {
        const double sigma_r = unit(rng) < 0.5 ? 0.005 : 0.01;
        const GlintPndf pndf(r, sigma_r);
        const double width = std::exp(std::log(256.0) * unit(rng));
        Query query = random_query(q, rng, sigma_r, width);
        if (n % 3 == 0) query.s = Vec2(0.01 * (2 * unit(rng) - 1), 0.01 * (2 * unit(rng) - 1));  // the flat ground
        PndfStatistics stats;
        const double fast = pndf.evaluate(query.footprint, query.s, &stats, true);
        const double exact = pndf.evaluate_brute_force(query.footprint, query.s);
        const double peak = normal_peak(sigma_r);
        aggregated += stats.nodes_aggregated;
        ASSERT_LE(std::abs(fast - exact), 0.03 * exact + 0.006 * peak + 1e-12)
            << glint_blend_mode_name(mode) << " width " << width << ": " << fast << " vs " << exact;
      }
    }
  }
  EXPECT_GT(aggregated, 1000u);  // the bound was tested where aggregation happens
}

// D_P integrates to 1 over normals, minus the mass the truncation drops (midpoint rule over the box holding
// every element's truncation box, step sigma_r / 4). The loss is printed: the element boxes (blended leaf
// intervals, which hold every sub-element of each example texel: element_normal_bounds.h) miss only the part of
// a blended element that comes from the blend weights' gradient. With one element per texel linearized on the
// field's kinks, `histogram` lost 4.2% here.
TEST(GlintPndf, IntegratesToOneOverNormalsUpToTruncation_AllModes) {
  const Fixture& f = fixture();
  const RmqTableView view = f.rmq16.view();
  for (const GlintBlendMode mode : kModes) {
    const GlintPointQuery q(f.example, 32, 4, mode, &f.lut.tables);
    const GlintRangeQuery r(q, view);
    const double sigma_r = 0.02;
    const GlintPndf pndf(r, sigma_r);
    const GlintFootprint fp{Vec2(-37.2, 81.9), 1.3};
    const TexelRange t = footprint_texels(fp);
    RmqBounds box{INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (int64_t t1 = t.t1_lo; t1 <= t.t1_hi; ++t1)
      for (int64_t t0 = t.t0_lo; t0 <= t.t0_hi; ++t0) {
        const RmqBounds b = r.element_bounds(t0, t1);
        box = {std::min(box.min_x, b.min_x), std::max(box.max_x, b.max_x), std::min(box.min_y, b.min_y),
               std::max(box.max_y, b.max_y)};
      }
    const double m = kGlintNormalCutoffSigmas * sigma_r, step = sigma_r / 4;
    double total = 0.0;
    for (double y = box.min_y - m; y < box.max_y + m; y += step)
      for (double x = box.min_x - m; x < box.max_x + m; x += step)
        total += pndf.evaluate(fp, Vec2(x + step / 2, y + step / 2));
    total *= step * step;
    std::printf("[ info ] mode %d: D_P integrates to %.5f\n", int(mode), total);
    EXPECT_LE(total, 1.0 + 1e-4);
    EXPECT_GE(total, 0.995);
  }
}

// >= 10^6 samples binned on a 16 x 16 grid over the normals they reach, against the P-NDF integrated over each
// bin (8 x 8 midpoint rule) and divided by its integral over the grid (the samples' density is D_P / its
// integral, glint_pndf.h: the truncated mass is not sampled): relative L1 = sum |histogram - expected| <= 2%.
TEST(GlintPndf, SampleHistogramMatchesPndf_RelativeL1Within2Percent) {
  const Fixture& f = fixture();
  const RmqTableView view = f.rmq16.view();
  for (const GlintBlendMode mode : {GlintBlendMode::histogram, GlintBlendMode::linear}) {
    const GlintPointQuery q(f.example, 32, 8, mode, &f.lut.tables);
    const GlintRangeQuery r(q, view);
    const GlintPndf pndf(r, 0.01);
    GlintFootprint fp{Vec2(412.3, -96.6), 2.0};
    std::mt19937_64 rng(77);
    if (mode == GlintBlendMode::linear) fp.slope << 0.01, -0.004, 0.002, 0.006;  // drawn with n', J'
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::function<double()> uniform = [&] { return unit(rng); };
    constexpr int kSamples = 1000000;
    std::vector<Vec2> samples;
    samples.reserve(kSamples);
    RmqBounds box{INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (int n = 0; n < kSamples; ++n) {
      const std::optional<Vec2> s = pndf.sample(fp, uniform);
      ASSERT_TRUE(s.has_value());
      samples.push_back(*s);
      box = {std::min(box.min_x, s->x()), std::max(box.max_x, s->x()), std::min(box.min_y, s->y()),
             std::max(box.max_y, s->y())};
    }
    constexpr int kBins = 16, kSub = 8;
    const double bx = (box.max_x - box.min_x) / kBins * (1 + 1e-9), by = (box.max_y - box.min_y) / kBins * (1 + 1e-9);
    std::vector<double> hist(kBins * kBins, 0.0), expected(kBins * kBins, 0.0);
    for (const Vec2& s : samples)
      hist[size_t(int((s.y() - box.min_y) / by) * kBins + int((s.x() - box.min_x) / bx))] += 1.0 / kSamples;
    double l1 = 0.0, mass = 0.0;
    for (int j = 0; j < kBins; ++j)
      for (int i = 0; i < kBins; ++i) {
        double integral = 0.0;
        for (int sj = 0; sj < kSub; ++sj)
          for (int si = 0; si < kSub; ++si)
            integral += pndf.evaluate(
                fp, Vec2(box.min_x + (i + (si + 0.5) / kSub) * bx, box.min_y + (j + (sj + 0.5) / kSub) * by));
        integral *= bx * by / (kSub * kSub);
        expected[size_t(j * kBins + i)] = integral;
        mass += integral;
      }
    for (size_t b = 0; b < hist.size(); ++b) l1 += std::abs(hist[b] - expected[b] / mass);
    std::printf("[ info ] sampling: relative L1 %.4f over %d samples, P-NDF mass in the grid %.5f\n", l1, kSamples,
                mass);
    EXPECT_LE(l1, 0.02);
  }
}

TEST(GlintPndf, FootprintWithoutTexelCentreIsZeroAndHasNoSample) {
  const Fixture& f = fixture();
  const RmqTableView view = f.rmq16.view();
  const GlintPointQuery q(f.example, 32, 9, GlintBlendMode::linear);
  const GlintRangeQuery r(q, view);
  const GlintPndf pndf(r, 0.01);
  const GlintFootprint tiny{Vec2(3.0, -7.0), 0.1};  // 3 sigma = 0.3: no centre t + 0.5 within
  EXPECT_TRUE(footprint_texels(tiny).empty());
  EXPECT_EQ(pndf.evaluate(tiny, Vec2(0, 0)), 0.0);
  EXPECT_EQ(pndf.evaluate_brute_force(tiny, Vec2(0, 0)), 0.0);
  EXPECT_FALSE(pndf.sample(tiny, [] { return 0.5; }).has_value());
  const GlintFootprint one{Vec2(3.5, -6.5), 0.1};  // exactly one centre
  const TexelRange t = footprint_texels(one);
  EXPECT_EQ(t.t0_lo, 3);
  EXPECT_EQ(t.t0_hi, 3);
  EXPECT_EQ(t.t1_lo, -7);
  EXPECT_EQ(t.t1_hi, -7);
}

TEST(GlintPndf, BadRoughnessOrFootprintIsRefused) {
  const Fixture& f = fixture();
  const RmqTableView view = f.rmq16.view();
  const GlintPointQuery q(f.example, 32, 9, GlintBlendMode::linear);
  const GlintRangeQuery r(q, view);
  EXPECT_THROW(GlintPndf(r, 0.0), Error);
  EXPECT_THROW(GlintPndf(r, NAN), Error);
  const GlintPndf pndf(r, 0.01);
  EXPECT_THROW(pndf.evaluate({Vec2(0, 0), 0.0}, Vec2(0, 0)), Error);
  EXPECT_THROW(pndf.evaluate({Vec2(NAN, 0), 1.0}, Vec2(0, 0)), Error);
  EXPECT_THROW(pndf.evaluate({Vec2(1e300, 0), 1.0}, Vec2(0, 0)), Error);
}

// The point of the traversal: at small roughness a large footprint is answered from fewer nodes than it has
// texels (how many fewer depends on the map: examples/results/glint/REPORT.md measures it).
TEST(GlintPndf, TraversalVisitsFewerNodesThanTexels) {
  const Fixture& f = fixture();
  const RmqTableView view = f.rmq16.view();
  const GlintPointQuery q(f.example, 32, 9, GlintBlendMode::histogram, &f.lut.tables);
  const GlintRangeQuery r(q, view);
  const GlintPndf pndf(r, 0.005);
  const GlintFootprint fp{Vec2(1000.0, 2000.0), 128.0 / 6};
  PndfStatistics stats;
  pndf.evaluate(fp, q.evaluate(fp.center).n, &stats);
  const TexelRange t = footprint_texels(fp);
  const uint64_t texels = uint64_t((t.t0_hi - t.t0_lo + 1) * (t.t1_hi - t.t1_lo + 1));
  std::printf("[ info ] %llu nodes, %llu elements evaluated for %llu texels\n", (unsigned long long)stats.nodes_visited,
              (unsigned long long)stats.elements_evaluated, (unsigned long long)texels);
  EXPECT_LT(stats.nodes_visited, texels);
  EXPECT_GT(stats.elements_evaluated, 0u);
}

// On a constant example every element is the same Gaussian around the constant normal with J = 0, so D_P equals
// the point NDF exactly, for any footprint; and the point NDF integrates to 1.
// A 64^2 example whose every texel has the normal components (0.2, -0.1), and its queries.
struct ConstantExample {
  NormalMap map{64, 64, std::vector<Vec3f>(64 * 64, Vec3f(0.2f, -0.1f, std::sqrt(1.0f - 0.05f)))};
  RmqTable table = build_rmq_table(map, 16, 16, Progress::silent());
  RmqTableView view = table.view();
  GlintPointQuery q{map, 16, 1, GlintBlendMode::variance};
  GlintRangeQuery r{q, view};
};

TEST(GlintPndf, ConstantExampleGivesThePointNdfForAnyFootprint) {
  const Vec2 c(0.2, -0.1);
  const ConstantExample example;
  const GlintPointQuery& q = example.q;
  const GlintPndf pndf(example.r, 0.01);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> v(-1.0, 1.0);
  for (int n = 0; n < 100; ++n) {
    const GlintFootprint fp{Vec2(100 * v(rng), 100 * v(rng)), 0.5 + 10 * std::abs(v(rng))};
    const Vec2 s = c + 0.03 * Vec2(v(rng), v(rng));
    const double reference = point_ndf(q, fp.center, 0.01, s);
    EXPECT_NEAR(pndf.evaluate(fp, s), reference, 1e-9 * reference + 1e-12);
  }
  double total = 0.0;
  const double step = 0.0025;
  for (double y = -0.1 - 0.08; y < -0.1 + 0.08; y += step)
    for (double x = 0.2 - 0.08; x < 0.2 + 0.08; x += step) total += point_ndf(q, Vec2(3, 4), 0.01, Vec2(x, y));
  EXPECT_NEAR(total * step * step, 1.0, 1e-6);
  EXPECT_THROW(point_ndf(q, Vec2(0, 0), 0.0, c), Error);
}

// The half vector's slope field in closed form (glint_pndf.h): on a constant example every point has normal n and
// J = 0, so a point u seeing s + K (u - c) contributes N(s + K (u - c); n, sigma_r^2 I), and
// (1) per sub-element, Eq. (1) with n' = n - K (u_i - c), J' = -K is m_i N(s; n - K (mu_i - c), sigma_r^2 I +
//     sigma_e^2 K K^T) (mu_i, sigma_e: the footprint-element product, position_normal_element.h): D_P is their
//     mass-weighted mean up to the normal truncation (< 1e-3 of the peak here);
// (2) the highlight's true footprint average, the integral of G_P(u) N(s + K (u - c); n, sigma_r^2 I) over u, is
//     N(s; n, sigma_r^2 I + sigma_p^2 K K^T); the P-NDF's sub-elements reproduce the footprint's covariance
//     exactly in the continuum, so D_P differs by the 3-sigma footprint truncation (its variance is 0.973
//     sigma_p^2, and it has no tails) and the sub-element lattice: relative L1 over a grid of s within 4
//     deviations of the highlight <= 4% (measured worst 3.2%, on the huge slopes),
// for slopes small, anisotropic, singular (rank 1) and huge, by traversal, aggregation and brute force.
TEST(GlintPndf, ConstantExampleWithASlopeFieldIsTheHighlightsFootprintAverage) {
  const ConstantExample example;
  const double sigma_r = 0.01;
  const GlintPndf pndf(example.r, sigma_r);
  const Vec2 n = example.q.evaluate(Vec2(3, 4)).n;  // the same everywhere
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> v(-1.0, 1.0);
  double worst_l1 = 0.0;
  for (int k = 0; k < 24; ++k) {
    GlintFootprint fp{Vec2(100 * v(rng), 100 * v(rng)), 1.0 + 3 * std::abs(v(rng))};
    fp.slope = random_slope(rng, sigma_r, 2 * kGlintFootprintCutoffSigmas * fp.sigma);
    if (k == 0) fp.slope << 0.05, 0.0, 0.0, 0.0;  // huge: the highlight spread over many sigma_r
    const Mat2 cov = sigma_r * sigma_r * Mat2::Identity() + fp.sigma * fp.sigma * fp.slope * fp.slope.transpose();
    const Eigen::SelfAdjointEigenSolver<Mat2> eigen(cov);
    const Mat2 root = eigen.operatorSqrt();
    // (1) the sum of sub-element Gaussians, from the masses and means of the footprint-element products.
    const TexelRange t = footprint_texels(fp);
    const double sh2 = kGlintSubElementSigmaTexels * kGlintSubElementSigmaTexels, sp2 = fp.sigma * fp.sigma;
    const double se2 = sp2 * sh2 / (sp2 + sh2);
    struct Part {
      double mass;
      Vec2 centre;
    };
    std::vector<Part> parts;
    double total = 0.0;
    for (int64_t t1 = t.t1_lo; t1 <= t.t1_hi; ++t1)
      for (int64_t t0 = t.t0_lo; t0 <= t.t0_hi; ++t0)
        for (int a1 = 0; a1 < 2; ++a1)
          for (int a0 = 0; a0 < 2; ++a0) {
            const Vec2 u(t0 + (a0 + 0.5) / 2, t1 + (a1 + 0.5) / 2);
            const Vec2 mu = (sh2 * fp.center + sp2 * u) / (sp2 + sh2);
            parts.push_back(
                {std::exp(-0.5 * (u - fp.center).squaredNorm() / (sp2 + sh2)), n - fp.slope * (mu - fp.center)});
            total += parts.back().mass;
          }
    const Mat2 element_cov = sigma_r * sigma_r * Mat2::Identity() + se2 * fp.slope * fp.slope.transpose();
    const Mat2 element_inv = element_cov.inverse();
    const double element_norm = 1.0 / (2 * std::numbers::pi * std::sqrt(element_cov.determinant()));
    const double peak = 1.0 / (2 * std::numbers::pi * std::sqrt(cov.determinant()));
    double l1 = 0.0, sum = 0.0;
    for (double zy = -4.0; zy <= 4.0; zy += 1.0)
      for (double zx = -4.0; zx <= 4.0; zx += 1.0) {
        const Vec2 s = n + root * Vec2(zx, zy);
        double parts_sum = 0.0;
        for (const Part& p : parts) {
          const Vec2 d = s - p.centre;
          parts_sum += p.mass * element_norm * std::exp(-0.5 * d.dot(element_inv * d));
        }
        parts_sum /= total;
        const double traversal = pndf.evaluate(fp, s);
        ASSERT_NEAR(traversal, parts_sum, 1e-3 * peak) << k << " (" << zx << ", " << zy << ")";
        ASSERT_NEAR(pndf.evaluate_brute_force(fp, s), traversal, 1e-9 * traversal + 1e-12);
        ASSERT_NEAR(pndf.evaluate(fp, s, nullptr, true), traversal, 0.03 * traversal + 0.006 * normal_peak(sigma_r));
        const Vec2 d = s - n;
        const double average = peak * std::exp(-0.5 * d.dot(cov.inverse() * d));
        l1 += std::abs(traversal - average);
        sum += average;
      }
    worst_l1 = std::max(worst_l1, l1 / sum);
    EXPECT_LE(l1 / sum, 0.04) << k << ": sigma_p " << fp.sigma << " |K| " << fp.slope.norm();
  }
  std::printf("[ info ] worst relative L1 against the footprint average: %.4f\n", worst_l1);
  GlintFootprint bad{Vec2(0, 0), 1.0};
  bad.slope << NAN, 0.0, 0.0, 0.0;
  EXPECT_THROW(pndf.evaluate(bad, n), Error);
  bad.slope << INFINITY, 0.0, 0.0, 0.0;
  EXPECT_THROW(pndf.evaluate_brute_force(bad, n), Error);
}

// Against brute force through the same blended microstructure: many sub-pixel points u over the footprint (a
// 0.1-texel grid over the truncation square, weighted by G_P), each seeing its own half vector s + K (u - c), their
// point NDFs averaged (what a renderer's rays per pixel converge to). The slope field must follow it about as well
// as the P-NDF follows the point NDFs without a slope (issue 11 part 3: the elements' linearization), and far
// better than the previous form, the pixel's sweep applied independent of position (here: D_P without a slope
// averaged over 8 x 8 half vectors s + K d, d over the footprint's box of width sqrt(12) sigma_p per axis).
// Relative L1 over normals s that some point of the footprint reflects, summed over footprints 1 to 3 texels
// (sigma_p), bumps, modes none and variance.
TEST(GlintPndf, SlopeFieldFollowsTheMeanOfPointNdfsOverTheFootprint) {
  const Fixture& f = fixture();
  const RmqTableView view = f.rmq16.view();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double sigma_r = 0.01;
  for (const GlintBlendMode mode : {GlintBlendMode::none, GlintBlendMode::variance}) {
    const GlintPointQuery q(f.example, 32, 9, mode, &f.lut.tables);
    const GlintRangeQuery r(q, view);
    const GlintPndf pndf(r, sigma_r);
    double err_still = 0.0, err_field = 0.0, err_positionless = 0.0, sum_still = 0.0, sum_swept = 0.0;
    for (int k = 0; k < 12; ++k) {
      GlintFootprint fp{Vec2(300 * unit(rng), 300 * unit(rng)), 1.0 + 2.0 * unit(rng)};
      const double box = std::sqrt(12.0) * fp.sigma;
      // The half vector sweeps 4-12 sigma_r along a random direction as the point crosses the footprint's box.
      const double angle = 2 * std::numbers::pi * unit(rng), turn = 2 * std::numbers::pi * unit(rng);
      const Mat2 slope = (4.0 + 8.0 * unit(rng)) * sigma_r / box * Vec2(std::cos(angle), std::sin(angle)) *
                         Vec2(std::cos(turn), std::sin(turn)).transpose();
      // The points of the footprint and their normals, once.
      std::vector<std::pair<Vec2, double>> points;  // (offset u - c, weight)
      std::vector<Vec2> normals;
      const double reach = kGlintFootprintCutoffSigmas * fp.sigma;
      for (double y = -reach + 0.05; y < reach; y += 0.1)
        for (double x = -reach + 0.05; x < reach; x += 0.1) {
          points.push_back({Vec2(x, y), std::exp(-0.5 * (x * x + y * y) / (fp.sigma * fp.sigma))});
          normals.push_back(q.evaluate(fp.center + Vec2(x, y)).n);
        }
      double weights = 0.0;
      for (const auto& p : points) weights += p.second;
      for (int j = 0; j < 16; ++j) {
        // s that point i of the footprint reflects with the field (so that the answers are not 0).
        const size_t i = size_t(unit(rng) * double(points.size()));
        const Vec2 s = normals[i] - slope * points[i].first + sigma_r * Vec2(unit(rng) - 0.5, unit(rng) - 0.5);
        double still = 0.0, swept = 0.0;
        for (size_t p = 0; p < points.size(); ++p) {
          const double ir2 = 1.0 / (sigma_r * sigma_r);
          still += points[p].second * std::exp(-0.5 * (s - normals[p]).squaredNorm() * ir2);
          swept += points[p].second * std::exp(-0.5 * (s + slope * points[p].first - normals[p]).squaredNorm() * ir2);
        }
        still /= weights * 2 * std::numbers::pi * sigma_r * sigma_r;
        swept /= weights * 2 * std::numbers::pi * sigma_r * sigma_r;
        GlintFootprint field = fp;
        field.slope = slope;
        double positionless = 0.0;
        for (int b = 0; b < 8; ++b)
          for (int a = 0; a < 8; ++a)
            positionless += pndf.evaluate(fp, s + slope * (box * Vec2((a + 0.5) / 8 - 0.5, (b + 0.5) / 8 - 0.5))) / 64;
        err_still += std::abs(pndf.evaluate(fp, s) - still);
        sum_still += still;
        err_field += std::abs(pndf.evaluate(field, s) - swept);
        err_positionless += std::abs(positionless - swept);
        sum_swept += swept;
      }
    }
    const double still = err_still / sum_still, field = err_field / sum_swept,
                 positionless = err_positionless / sum_swept;
    std::printf(
        "[ info ] %s: relative L1 against the point NDFs' mean: no sweep %.3f; swept: slope field %.3f, "
        "position-independent sweep %.3f\n",
        glint_blend_mode_name(mode), still, field, positionless);
    EXPECT_LE(field, 1.25 * still + 0.02) << glint_blend_mode_name(mode);
    EXPECT_LE(field, 0.5 * positionless) << glint_blend_mode_name(mode);
  }
}

}  // namespace
}  // namespace mbk
