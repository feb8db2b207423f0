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
#include <vector>

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

// A pixel's half-vector sweep (glint_pndf.h, "Directional spread"): a covariance with standard deviations up to
// 10 sigma_r along a random direction and up to sigma_r across it, as at grazing angles.
Mat2 random_sweep(std::mt19937_64& rng, double sigma_r) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double angle = 2 * std::numbers::pi * unit(rng), along = 10 * sigma_r * unit(rng), across = sigma_r * unit(rng);
  const Vec2 u(std::cos(angle), std::sin(angle)), w(-u.y(), u.x());
  const Mat2 c = along * along * u * u.transpose() + across * across * w * w.transpose();
  return 0.5 * (c + c.transpose());  // exactly symmetric
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
  if (unit(rng) < 0.4) out.footprint.sweep = random_sweep(rng, sigma_r);
  return out;
}

// The peak of the elements' normal Gaussian, 1 / (2 pi sqrt(det C)) with C = sigma_r^2 I + the sweep.
double normal_peak(double sigma_r, const Mat2& sweep) {
  return 1.0 / (2.0 * std::numbers::pi * std::sqrt((sigma_r * sigma_r * Mat2::Identity() + sweep).determinant()));
}

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

// evaluate_mean over several normals in one traversal (a pixel's sweep cells, pixel_sweep.h) against the mean of
// brute force at each, 1e-5 relative, every mode, 1 to 12 normals spread over up to 20 sigma_r.
TEST(GlintPndf, MeanOverNormalsEqualsTheMeanOfBruteForce) {
  const Fixture& f = fixture();
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const RmqTableView view = f.rmq16.view();
  int nonzero = 0;
  for (const GlintBlendMode mode : kModes) {
    const GlintPointQuery q(f.example, 32, 9, mode, &f.lut.tables);
    const GlintRangeQuery r(q, view);
    const GlintPndf pndf(r, 0.01);
    for (int n = 0; n < 50; ++n) {
      const Query base = random_query(q, rng, 0.01, std::exp(std::log(64.0) * unit(rng)));
      std::vector<Vec2> normals(size_t(1 + int(12 * unit(rng))));
      double brute = 0.0;
      for (Vec2& s : normals) {
        s = base.s + 0.2 * Vec2(unit(rng) - 0.5, unit(rng) - 0.5);
        brute += pndf.evaluate_brute_force(base.footprint, s) / double(normals.size());
      }
      const double mean = pndf.evaluate_mean(base.footprint, normals);
      ASSERT_NEAR(mean, brute, 1e-5 * brute) << glint_blend_mode_name(mode) << " " << normals.size() << " normals";
      nonzero += brute > 0.0;
    }
  }
  EXPECT_GT(nonzero, 150);
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
// within the stated bound |D_agg - D| <= 0.03 D + 0.006 / (2 pi sqrt(det C)): maps of smooth bumps and of flat
// ground cut by scratches (where aggregation pays), every blend mode, footprints 1 to 256 texels wide, 40% of
// them with an anisotropic sweep.
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
        const double peak = normal_peak(sigma_r, query.footprint.sweep);
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
    if (mode == GlintBlendMode::linear) fp.sweep << 2.5e-4, 1e-4, 1e-4, 1e-4;  // anisotropic: drawn by C^(1/2)
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

// With a sweep S the same elements are the Gaussian N(s; n, sigma_r^2 I + S) (glint_pndf.h, "Directional
// spread"), in closed form: the whitening and its det factor, for anisotropic and correlated sweeps, by
// traversal, aggregation and brute force; a sweep that is not a covariance is refused.
TEST(GlintPndf, ConstantExampleWithASweepGivesTheWidenedGaussian) {
  const Vec2 c(0.2, -0.1);
  const ConstantExample example;
  const GlintPointQuery& q = example.q;
  const double sigma_r = 0.01;
  const GlintPndf pndf(example.r, sigma_r);
  const Vec2 n = q.evaluate(Vec2(3, 4)).n;  // the same everywhere
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> v(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    GlintFootprint fp{Vec2(100 * v(rng), 100 * v(rng)), 0.5 + 10 * std::abs(v(rng))};
    fp.sweep = random_sweep(rng, sigma_r);
    const Mat2 cov = sigma_r * sigma_r * Mat2::Identity() + fp.sweep;
    const Vec2 s = c + 0.05 * Vec2(v(rng), v(rng));
    const Vec2 d = s - n;
    const double gaussian =
        std::exp(-0.5 * d.dot(cov.inverse() * d)) / (2 * std::numbers::pi * std::sqrt(cov.determinant()));
    // Inside the truncation box (4 sqrt(C_ii) per component) the elements are whole; outside they are 0.
    const bool inside = std::abs(d.x()) <= 4 * std::sqrt(cov(0, 0)) && std::abs(d.y()) <= 4 * std::sqrt(cov(1, 1));
    const double expected = inside ? gaussian : 0.0;
    EXPECT_NEAR(pndf.evaluate(fp, s), expected, 1e-9 * expected + 1e-12) << k;
    EXPECT_NEAR(pndf.evaluate(fp, s, nullptr, true), expected, 1e-9 * expected + 1e-12) << k;
    EXPECT_NEAR(pndf.evaluate_brute_force(fp, s), expected, 1e-9 * expected + 1e-12) << k;
  }
  GlintFootprint bad{Vec2(0, 0), 1.0};
  for (const Mat2& sweep : {Mat2{{-1e-4, 0.0}, {0.0, 1e-4}}, Mat2{{1e-4, 2e-4}, {2e-4, 1e-4}},
                            Mat2{{1e-4, 0.0}, {1e-5, 1e-4}}, Mat2{{NAN, 0.0}, {0.0, 1e-4}}}) {
    bad.sweep = sweep;
    EXPECT_THROW(pndf.evaluate(bad, c), Error);
  }
}

}  // namespace
}  // namespace mbk
