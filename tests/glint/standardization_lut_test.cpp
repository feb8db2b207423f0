// Standardization knots of whole example maps (libbake/glint/standardization_sampling.h, lut_asset.h), against the
// exact transform (empirical_standardization.h): G_T within its knot interval's z step of G and G^-1_T within its
// x step of G^-1 (each at most one grid step), exact at every atom, round trips exact, for every generated kind,
// the real maps and maps that are mostly one value; slopes that are the finite differences of the interpolant;
// clamped lookups; the clipped tail mass; and the hard cases (constant, two-valued, nearly constant, 1 x 1 maps).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "formats/lut_layout.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/empirical_standardization.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/standard_normal.h"
#include "libbake/glint/standardization_sampling.h"
#include "libbake/image/normal_map.h"
#include "tests/glint/atom_maps.h"
#include "tests/real_normal_maps.h"

namespace mbk {
namespace {

std::vector<float> channel(const NormalMap& map, int c) {
  std::vector<float> v;
  for (const Vec3f& n : map.texels) v.push_back(n[c]);
  return v;
}

// Knots strictly increasing in both axes, ends at the exact domain, every atom (a value of >= N / size
// texels) a knot with its exact mid-rank z, G_T and G^-1_T within the bounds of standardization_sampling.h at the
// example's values and at 2001 evenly spread points, and round trips exact.
void expect_exact_knot_tables(const std::vector<float>& values, uint32_t size, const std::string& what) {
  const EmpiricalStandardization g(values);
  const StandardizationChannelTables t = sample_standardization(g, size);
  SCOPED_TRACE(what + ", size " + std::to_string(size));
  ASSERT_GE(t.knots(), 1u);
  ASSERT_LE(t.knots(), lut_max_knots(size));
  for (size_t i = 1; i < t.knots(); ++i) {
    ASSERT_LT(t.x()[i - 1], t.x()[i]) << i;
    ASSERT_LT(t.z()[i - 1], t.z()[i]) << i;
  }
  EXPECT_EQ(t.x_lo(), float(g.min()));
  if (t.knots() == 1) return;  // a constant channel, checked by its own test
  EXPECT_EQ(t.x_hi(), float(g.max()));
  EXPECT_EQ(t.z_lo(), float(g.gaussian_min()));
  EXPECT_EQ(t.z_hi(), float(g.gaussian_max()));
  // The construction: every point of both grids (rounded to float) is a knot, unless its z rounds onto a
  // neighbouring knot's (then that knot stands for it). So consecutive knots are at most one grid step apart in
  // each axis, up to the float rounding of x (which moves z by G' times half an ulp: 1e-5 of a 2e-3 step was
  // measured where two distinct values lie 1e-6 apart).
  const std::span<const float> kx = t.x(), kz = t.z();
  auto expect_knot = [&](float x, const char* grid, uint32_t j) {
    const auto it = std::lower_bound(kx.begin(), kx.end(), x);
    if (it != kx.end() && *it == x) return;
    const float z = float(g.forward(x));
    const size_t i = size_t(it - kx.begin());
    const bool stood_for = (i < kx.size() && kz[i] == z) || (i > 0 && kz[i - 1] == z);
    ASSERT_TRUE(stood_for) << grid << " grid point " << j << " (x " << x << ") is no knot";
  };
  for (uint32_t j = 0; j < size; ++j) {
    expect_knot(float(lut_sample_position(g.min(), g.max(), size, j)), "x", j);
    expect_knot(float(g.inverse(lut_sample_position(g.gaussian_min(), g.gaussian_max(), size, j))), "z", j);
  }
  // Between its knots each map is monotone and agrees with the exact one at both ends (up to float rounding of
  // z, 1e-7 relative): so the error at any point is at most its interval's step.
  auto interval = [](std::span<const float> keys, double q) {
    size_t i =
        size_t(std::upper_bound(keys.begin(), keys.end(), q, [](double a, float b) { return a < b; }) - keys.begin());
    return std::min(i == 0 ? 0 : i - 1, keys.size() - 2);
  };
  auto z_gap = [&](double x) {
    const size_t i = interval(kx, x);
    return double(kz[i + 1]) - kz[i];
  };
  auto x_gap = [&](double z) {
    const size_t i = interval(kz, z);
    return double(kx[i + 1]) - kx[i];
  };
  const uint64_t heavy = (values.size() + size - 1) / size;
  for (float atom : g.values_counted_at_least(std::max<uint64_t>(heavy, 1)))
    ASSERT_NEAR(t.standardize(atom).value, g.forward(atom), 1e-7 * std::max(1.0, std::abs(g.forward(atom)))) << atom;
  for (float u : g.distinct()) {
    ASSERT_LE(std::abs(t.standardize(u).value - g.forward(u)), z_gap(u) + 1e-6) << u;
    ASSERT_NEAR(t.destandardize(t.standardize(u).value).value, u, 1e-12 + 1e-7 * std::abs(u)) << u;
  }
  for (int i = 0; i <= 2000; ++i) {
    const double z = g.gaussian_min() + (g.gaussian_max() - g.gaussian_min()) * i / 2000.0;
    ASSERT_LE(std::abs(t.destandardize(z).value - g.inverse(z)), x_gap(z) + 1e-6) << z;
    const double x = g.min() + (g.max() - g.min()) * i / 2000.0;
    ASSERT_LE(std::abs(t.standardize(x).value - g.forward(x)), z_gap(x) + 1e-6) << x;
  }
}

class GeneratedKinds : public ::testing::TestWithParam<std::string> {};

TEST_P(GeneratedKinds, KnotsWithinOneStepOfTheExactTransform) {
  const NormalMap map = generate_normal_map(GetParam(), {256, 256}, 7, Progress::silent());
  for (uint32_t size : {2u, 128u, kLutDefaultSize, 65536u})
    for (int c = 0; c < 2; ++c) expect_exact_knot_tables(channel(map, c), size, GetParam() + " channel " + "xy"[c]);
}

TEST_P(GeneratedKinds, StatisticsAreTheMeasuredErrors) {
  const NormalMap map = generate_normal_map(GetParam(), {96, 64}, 3, Progress::silent());
  const BakedLut lut = bake_standardization_lut(map, 512, Progress::silent());
  for (int c = 0; c < 2; ++c) {
    const EmpiricalStandardization g(channel(map, c));
    const StandardizationChannelTables& t = lut.tables.channels[c];
    double forward = 0.0, round_trip = 0.0;
    for (float u : g.distinct()) {
      forward = std::max(forward, std::abs(t.standardize(u).value - g.forward(u)));
      round_trip = std::max(round_trip, std::abs(t.destandardize(t.standardize(u).value).value - double(u)));
    }
    EXPECT_EQ(lut.statistics[c].forward_error, forward);
    EXPECT_EQ(lut.statistics[c].round_trip_error, round_trip);
    EXPECT_LE(round_trip, 1e-7);
    EXPECT_EQ(lut.statistics[c].knots, t.knots());
    EXPECT_LE(lut.statistics[c].inverse_error, (g.max() - g.min()) / 511 + 1e-6);
  }
}

INSTANTIATE_TEST_SUITE_P(StandardizationLut, GeneratedKinds,
                         ::testing::Values("bumps", "brushed", "scratches", "flakes", "leather", "panels"));

TEST(StandardizationLut, KnotsWithinOneStepOfTheExactTransform_AtomMaps) {
  // 50-99% of texels one value (the flat ground of scratches and panels), a two-valued map, a constant map.
  for (const test::AtomMap& m : test::atom_maps())
    for (uint32_t size : {2u, 128u, kLutDefaultSize, 65536u})
      for (int c = 0; c < 2; ++c) expect_exact_knot_tables(channel(m.map, c), size, m.name + " channel " + "xy"[c]);
}

TEST(StandardizationLut, KnotsWithinOneStepOfTheExactTransform_RealMaps) {
  const int maps = test::for_each_real_normal_map([](const NormalMap& map, const std::string& name) {
    for (uint32_t size : {128u, kLutDefaultSize})
      for (int c = 0; c < 2; ++c) expect_exact_knot_tables(channel(map, c), size, name);
  });
  if (maps == 0) GTEST_SKIP() << "no real normal maps in " << MICROBAKE_REAL_DATA_DIR;
}

TEST(StandardizationLut, AtomIsExactWhateverTheSize) {
  // The case behind the bug: ~93% of texels share x0 (scratches' flat ground). G(x0) is the mid-rank value,
  // near 0; tables sampled uniformly in x gave +0.61 at 4096 samples, +1.29 at 32768 and -1.08 at 65536.
  const NormalMap map = generate_normal_map("scratches", {256, 256}, 7, Progress::silent());
  for (int c = 0; c < 2; ++c) {
    const EmpiricalStandardization g(channel(map, c));
    const std::vector<float> atoms = g.values_counted_at_least(map.texels.size() / 2);
    ASSERT_EQ(atoms.size(), 1u) << "scratches should be mostly one value";
    for (uint32_t size : {2u, 128u, 4096u, 32768u, 65536u}) {
      const StandardizationChannelTables t = sample_standardization(g, size);
      EXPECT_NEAR(t.standardize(atoms[0]).value, g.forward(atoms[0]), 1e-6) << size;
      EXPECT_EQ(t.destandardize(t.standardize(atoms[0]).value).value, double(atoms[0])) << size;
    }
  }
}

TEST(StandardizationLut, SlopesAreFiniteDifferencesOfTheInterpolant) {
  const NormalMap map = generate_normal_map("leather", {64, 64}, 2, Progress::silent());
  const BakedLut lut = bake_standardization_lut(map, 300, Progress::silent());
  for (const StandardizationChannelTables& t : lut.tables.channels)
    for (bool forward : {true, false}) {
      const std::span<const float> keys = forward ? t.x() : t.z();
      for (size_t i = 0; i + 1 < keys.size(); ++i)
        for (double f : {0.3, 0.5, 0.7}) {  // inside knot interval i, away from its ends
          const double step = double(keys[i + 1]) - double(keys[i]), x = keys[i] + f * step, h = 0.1 * step;
          auto at = [&](double q) { return forward ? t.standardize(q) : t.destandardize(q); };
          const double fd = (at(x + h).value - at(x - h).value) / (2 * h);
          ASSERT_NEAR(at(x).derivative, fd, 1e-6 * std::max(1.0, std::abs(fd))) << "interval " << i;
        }
    }
}

TEST(StandardizationLut, LookupsClampOutsideTheirDomain) {
  const NormalMap map = generate_normal_map("bumps", {64, 64}, 1, Progress::silent());
  const BakedLut lut = bake_standardization_lut(map, 256, Progress::silent());
  for (const StandardizationChannelTables& t : lut.tables.channels) {
    EXPECT_EQ(t.standardize(t.x_lo() - 0.5).value, t.z_lo());
    EXPECT_EQ(t.standardize(t.x_hi() + 0.5).value, t.z_hi());
    EXPECT_EQ(t.standardize(t.x_hi() + 0.5).derivative, 0.0);
    EXPECT_EQ(t.standardize(std::nan("")).value, t.z_lo());
    // Beyond [G(min), G(max)] the exact G^-1 is the clamped min or max: the table says so with derivative 0.
    for (double z : {-40.0, double(t.z_lo()) - 1e-3, -std::numeric_limits<double>::infinity()}) {
      EXPECT_EQ(t.destandardize(z).value, t.x_lo());
      EXPECT_EQ(t.destandardize(z).derivative, 0.0);
    }
    for (double z : {double(t.z_hi()) + 1e-3, 40.0, std::numeric_limits<double>::infinity()}) {
      EXPECT_EQ(t.destandardize(z).value, t.x_hi());
      EXPECT_EQ(t.destandardize(z).derivative, 0.0);
    }
  }
}

TEST(StandardizationLut, TailMassIsTheEndRanks) {
  const NormalMap map = generate_normal_map("panels", {96, 80}, 4, Progress::silent());
  const BakedLut lut = bake_standardization_lut(map, kLutDefaultSize, Progress::silent());
  for (int c = 0; c < 2; ++c) {
    // Brute force: (texels at the minimum + texels at the maximum) / 2N.
    const std::vector<float> v = channel(map, c);
    const float lo = *std::min_element(v.begin(), v.end()), hi = *std::max_element(v.begin(), v.end());
    const double mass =
        double(std::count(v.begin(), v.end(), lo) + std::count(v.begin(), v.end(), hi)) / (2.0 * v.size());
    // The stored range is G(min), G(max) rounded to float: the mass moves by phi(z) times half an ulp of z.
    EXPECT_NEAR(lut.statistics[c].clipped_tail_mass, mass, 1e-6 * mass) << c;
  }
}

TEST(StandardizationLut, ConstantAndTwoValuedChannels) {
  // A flat map: both channels constant 0. A V-groove map: n_x two-valued (+-0.6), n_y constant.
  const NormalMap flat = test::map_of(7, 5, [](uint32_t, uint32_t) { return Vec3f(0, 0, 1); });
  const NormalMap groove =
      test::map_of(8, 3, [](uint32_t x, uint32_t) { return Vec3f(x < 4 ? -0.6f : 0.6f, 0, 0.8f); });
  for (const NormalMap* map : {&flat, &groove})
    for (uint32_t size : {2u, 128u, kLutDefaultSize}) {
      const BakedLut lut = bake_standardization_lut(*map, size, Progress::silent());
      for (int c = 0; c < 2; ++c) {
        const StandardizationChannelTables& t = lut.tables.channels[c];
        const bool constant = (map == &flat) || c == 1;
        if (constant) {
          ASSERT_EQ(t.knots(), 1u);
          EXPECT_EQ(t.z_lo(), 0.0f);
          for (double q : {-1.0, 0.0, 0.3, 2.0}) {
            EXPECT_EQ(t.standardize(q).value, 0.0);
            EXPECT_EQ(t.standardize(q).derivative, 0.0);
            EXPECT_EQ(t.destandardize(q).value, t.x_lo());
            EXPECT_EQ(t.destandardize(q).derivative, 0.0);
          }
          EXPECT_EQ(lut.statistics[c].clipped_tail_mass, 1.0);
          EXPECT_EQ(lut.statistics[c].round_trip_error, 0.0);
        } else {
          // Two values with equal counts: G(-0.6) = Phi^-1(1/4), G(0.6) = Phi^-1(3/4) exactly at the knots,
          // G^-1 flat (derivative 0) beyond them.
          EXPECT_NEAR(t.standardize(-0.6f).value, standard_normal_quantile(0.25), 1e-7);
          EXPECT_NEAR(t.standardize(0.6f).value, standard_normal_quantile(0.75), 1e-7);
          EXPECT_GT(t.standardize(0.0).derivative, 0.0);
          EXPECT_EQ(t.destandardize(-1.0).derivative, 0.0);
          EXPECT_EQ(t.destandardize(-1.0).value, t.x_lo());
          EXPECT_NEAR(lut.statistics[c].clipped_tail_mass, 0.5, 1e-6);
          EXPECT_LE(lut.statistics[c].round_trip_error, 1e-7);
        }
      }
    }
}

TEST(StandardizationLut, OneByOneMap) {
  const NormalMap one = test::map_of(1, 1, [](uint32_t, uint32_t) { return Vec3f(0.3f, -0.2f, 0.9f); });
  const BakedLut lut = bake_standardization_lut(one, 16, Progress::silent());
  for (int c = 0; c < 2; ++c) {
    EXPECT_EQ(lut.tables.channels[c].x_lo(), one.texels[0][c]);
    EXPECT_EQ(lut.tables.channels[c].destandardize(0.7).value, one.texels[0][c]);
    EXPECT_EQ(lut.statistics[c].distinct_values, 1u);
  }
}

TEST(StandardizationLut, NearlyConstantChannelStaysFinite) {
  // n_x spans two adjacent tiny floats (1e-38 apart): G' would be ~1e42, beyond float. Stored as a constant.
  const float tiny = std::numeric_limits<float>::min();
  NormalMap map{4, 1, {}};
  for (int i = 0; i < 4; ++i) map.texels.push_back(Vec3f(i < 2 ? tiny : std::nextafter(tiny, 1.0f), 0.0f, 1.0f));
  const BakedLut lut = bake_standardization_lut(map, kLutDefaultSize, Progress::silent());
  const StandardizationChannelTables& t = lut.tables.channels[0];
  EXPECT_EQ(t.knots(), 1u);
  EXPECT_LE(lut.statistics[0].round_trip_error, kFlatChannelSpread);
  // A spread of 1e-6 is not flat: real knots, finite slopes.
  for (int i = 0; i < 4; ++i) map.texels[i][0] = 0.1f + 1e-6f * float(i);
  const BakedLut fine = bake_standardization_lut(map, kLutDefaultSize, Progress::silent());
  EXPECT_LT(fine.tables.channels[0].x_lo(), fine.tables.channels[0].x_hi());
  for (double x = 0.1; x < 0.1 + 3e-6; x += 1e-7)
    ASSERT_TRUE(std::isfinite(fine.tables.channels[0].standardize(x).derivative));
}

TEST(StandardizationLut, SizeOutOfRangeIsRefused) {
  const NormalMap map = test::map_of(2, 2, [](uint32_t x, uint32_t) { return Vec3f(0.1f * x, 0, 1); });
  EXPECT_THROW(bake_standardization_lut(map, 1, Progress::silent()), Error);
  EXPECT_THROW(bake_standardization_lut(map, kLutMaxSize + 1, Progress::silent()), Error);
  EXPECT_NO_THROW(bake_standardization_lut(map, kLutMaxSize, Progress::silent()));
}

}  // namespace
}  // namespace mbk
