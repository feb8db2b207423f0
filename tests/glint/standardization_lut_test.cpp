// Standardization tables of whole example maps (libbake/glint/standardization_sampling.h, lut_asset.h): the round
// trip through the tables within one forward step (so <= 1e-3 at the default size) for every generated kind and
// the real maps, forward samples within one inverse step of the exact G, monotone tables whose slopes are the
// finite differences of their interpolants, clamped lookups, the clipped tail mass, and the hard cases (constant,
// two-valued, nearly constant, 1 x 1 maps).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "formats/lut_layout.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/empirical_standardization.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/standard_normal.h"
#include "libbake/glint/standardization_sampling.h"
#include "libbake/image/normal_map.h"

namespace mbk {
namespace {

std::vector<float> channel(const NormalMap& map, int c) {
  std::vector<float> v;
  for (const Vec3f& n : map.texels) v.push_back(n[c]);
  return v;
}

NormalMap map_of(uint32_t w, uint32_t h, const std::function<Vec3f(uint32_t, uint32_t)>& normal) {
  NormalMap m{w, h, {}};
  for (uint32_t row = 0; row < h; ++row)
    for (uint32_t x = 0; x < w; ++x) m.texels.push_back(normal(x, row).normalized());
  return m;
}

// max |G^-1_T(G_T(x)) - x| over the example's values, and the bound of standardization_sampling.h: one forward
// step, plus what float rounding of the stored z can move the inverse (its largest slope times half an ulp of z).
struct RoundTrip {
  double error = 0.0, bound = 0.0;
};
RoundTrip round_trip(const StandardizationChannelTables& t, const std::vector<float>& values, uint32_t size) {
  RoundTrip r;
  for (float v : values) r.error = std::max(r.error, std::abs(t.destandardize(t.standardize(v).value).value - v));
  double steepest = 0.0;
  for (float s : t.inverse_slope) steepest = std::max(steepest, double(s));
  const double z_ulp = 0x1p-24 * std::max(std::abs(t.z_lo), std::abs(t.z_hi));
  r.bound = (double(t.x_hi) - double(t.x_lo)) / (size - 1) + steepest * z_ulp + 1e-9;
  return r;
}

void expect_monotone_with_exact_slopes(const StandardizationChannelTables& t, const std::string& what) {
  for (const auto& [name, table] : {std::pair{"forward", t.forward_table()}, {"inverse", t.inverse_table()}}) {
    const uint32_t size = uint32_t(table.values.size());
    ASSERT_EQ(table.slopes.size(), size - 1);
    for (uint32_t j = 0; j + 1 < size; ++j) {
      ASSERT_TRUE(std::isfinite(table.values[j]) && std::isfinite(table.slopes[j])) << what << name << j;
      ASSERT_LE(table.values[j], table.values[j + 1]) << what << " " << name << " sample " << j;
      ASSERT_GE(table.slopes[j], 0.0f) << what << " " << name << " slope " << j;
    }
  }
}

class GeneratedKinds : public ::testing::TestWithParam<std::string> {};

TEST_P(GeneratedKinds, RoundTripWithinOneForwardStep_GeneratedKinds) {
  const NormalMap map = generate_normal_map(GetParam(), {256, 256}, 7, Progress::silent());
  for (uint32_t size : {kLutDefaultSize, 128u, 2u}) {
    const BakedLut lut = bake_standardization_lut(map, size, Progress::silent());
    for (int c = 0; c < 2; ++c) {
      const RoundTrip r = round_trip(lut.tables.channels[c], channel(map, c), size);
      EXPECT_LE(r.error, r.bound) << GetParam() << " channel " << c << " size " << size;
      EXPECT_DOUBLE_EQ(lut.statistics[c].round_trip_error, r.error);
      if (size == kLutDefaultSize) {
        EXPECT_LE(r.error, 1e-3) << GetParam() << " channel " << c;  // issue 3, section 4
      }
      expect_monotone_with_exact_slopes(lut.tables.channels[c], GetParam());
    }
  }
}

TEST_P(GeneratedKinds, ForwardSamplesWithinOneInverseStepOfG) {
  const NormalMap map = generate_normal_map(GetParam(), {128, 128}, 3, Progress::silent());
  for (int c = 0; c < 2; ++c) {
    const EmpiricalStandardization g(channel(map, c));
    const StandardizationChannelTables t = sample_standardization(g, 1024);
    const double inverse_step = (double(t.z_hi) - double(t.z_lo)) / 1023;
    for (uint32_t j = 0; j < 1024; ++j) {
      const double x = lut_sample_position(t.x_lo, t.x_hi, 1024, j);
      // Both lie between the inverse samples that bracket x; float rounding of those samples (half an ulp of x)
      // can move G by G' times that, which an atom makes steep: allow 1e-3 on top.
      ASSERT_NEAR(t.forward[j], g.forward(x), inverse_step + 1e-3) << GetParam() << " channel " << c << " j " << j;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(StandardizationLut, GeneratedKinds,
                         ::testing::Values("bumps", "brushed", "scratches", "flakes", "leather", "panels"));

TEST(StandardizationLut, RoundTripWithinOneThousandth_RealMaps) {
  const std::filesystem::path dir = MICROBAKE_REAL_DATA_DIR;
  if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "no real maps in " << dir;
  int maps = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".png" || e.path().stem().string().ends_with("_height")) continue;
    const LoadedNormalMap in = load_normal_map(e.path(), {YConvention::minus_y, InvalidTexelPolicy::repair});
    const BakedLut lut = bake_standardization_lut(in.map, kLutDefaultSize, Progress::silent());
    for (int c = 0; c < 2; ++c) {
      const RoundTrip r = round_trip(lut.tables.channels[c], channel(in.map, c), kLutDefaultSize);
      EXPECT_LE(r.error, std::min(r.bound, 1e-3)) << e.path() << " channel " << c;
      expect_monotone_with_exact_slopes(lut.tables.channels[c], e.path().string());
    }
    ++maps;
  }
  if (maps == 0) GTEST_SKIP() << "no normal maps in " << dir;
}

TEST(StandardizationLut, SlopesAreFiniteDifferencesOfTheInterpolant) {
  const NormalMap map = generate_normal_map("leather", {64, 64}, 2, Progress::silent());
  const BakedLut lut = bake_standardization_lut(map, 300, Progress::silent());
  for (const StandardizationChannelTables& t : lut.tables.channels)
    for (const LutTableView& table : {t.forward_table(), t.inverse_table()}) {
      const double step = (table.hi - table.lo) / 299;
      for (uint32_t j = 0; j < 299; ++j) {
        // Central difference inside interval j, away from its ends (the interpolant is linear there).
        for (double f : {0.3, 0.5, 0.7}) {
          const double x = table.lo + (j + f) * step, h = 0.1 * step;
          const double fd = (lut_lookup(table, x + h).value - lut_lookup(table, x - h).value) / (2 * h);
          const double d = lut_lookup(table, x).derivative;
          ASSERT_NEAR(d, fd, 1e-6 * std::max(1.0, std::abs(fd))) << "interval " << j;
        }
      }
    }
}

TEST(StandardizationLut, LookupsClampOutsideTheirDomain) {
  const NormalMap map = generate_normal_map("bumps", {64, 64}, 1, Progress::silent());
  const BakedLut lut = bake_standardization_lut(map, 256, Progress::silent());
  for (const StandardizationChannelTables& t : lut.tables.channels) {
    EXPECT_EQ(t.standardize(t.x_lo - 0.5).value, t.z_lo);
    EXPECT_EQ(t.standardize(t.x_hi + 0.5).value, t.z_hi);
    EXPECT_EQ(t.standardize(t.x_hi + 0.5).derivative, 0.0);
    // Beyond [G(min), G(max)] the exact G^-1 is the clamped min or max: the table says so with derivative 0.
    for (double z : {-40.0, double(t.z_lo) - 1e-3}) {
      EXPECT_EQ(t.destandardize(z).value, t.x_lo);
      EXPECT_EQ(t.destandardize(z).derivative, 0.0);
    }
    for (double z : {double(t.z_hi) + 1e-3, 40.0, std::numeric_limits<double>::infinity()}) {
      EXPECT_EQ(t.destandardize(z).value, t.x_hi);
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

TEST(StandardizationLut, ConstantChannelIsFlatAndFinite) {
  // A flat map: both channels constant 0. A V-groove map: n_x two-valued (+-0.6), n_y constant.
  const NormalMap flat = map_of(7, 5, [](uint32_t, uint32_t) { return Vec3f(0, 0, 1); });
  const NormalMap groove = map_of(8, 3, [](uint32_t x, uint32_t) { return Vec3f(x < 4 ? -0.6f : 0.6f, 0, 0.8f); });
  for (const NormalMap* map : {&flat, &groove})
    for (uint32_t size : {2u, 128u, kLutDefaultSize}) {
      const BakedLut lut = bake_standardization_lut(*map, size, Progress::silent());
      for (int c = 0; c < 2; ++c) {
        const StandardizationChannelTables& t = lut.tables.channels[c];
        expect_monotone_with_exact_slopes(t, "hard case");
        const bool constant = (map == &flat) || c == 1;
        if (constant) {
          EXPECT_EQ(t.z_lo, 0.0f);
          EXPECT_EQ(t.z_hi, 0.0f);
          for (float v : t.forward) ASSERT_EQ(v, 0.0f);
          for (float v : t.inverse) ASSERT_EQ(v, t.x_lo);
          for (float s : t.forward_slope) ASSERT_EQ(s, 0.0f);
          for (float s : t.inverse_slope) ASSERT_EQ(s, 0.0f);
          EXPECT_EQ(lut.statistics[c].clipped_tail_mass, 1.0);
          EXPECT_EQ(lut.statistics[c].round_trip_error, 0.0);
        } else {
          // Two values with equal counts: G(-0.6) = Phi^-1(1/4), G(0.6) = Phi^-1(3/4); G^-1 rises between them
          // and is flat (derivative 0) beyond them.
          EXPECT_NEAR(t.z_lo, standard_normal_quantile(0.25), 1e-7);
          EXPECT_NEAR(t.z_hi, standard_normal_quantile(0.75), 1e-7);
          for (float s : t.forward_slope) ASSERT_GT(s, 0.0f);
          EXPECT_EQ(t.destandardize(-1.0).derivative, 0.0);
          EXPECT_EQ(t.destandardize(1.0).derivative, 0.0);
          EXPECT_EQ(t.destandardize(-1.0).value, t.x_lo);
          EXPECT_NEAR(lut.statistics[c].clipped_tail_mass, 0.5, 1e-6);
          EXPECT_LE(lut.statistics[c].round_trip_error, 1e-6);  // the two values are the domain's ends
        }
      }
    }
}

TEST(StandardizationLut, OneByOneMap) {
  const NormalMap one = map_of(1, 1, [](uint32_t, uint32_t) { return Vec3f(0.3f, -0.2f, 0.9f); });
  const BakedLut lut = bake_standardization_lut(one, 16, Progress::silent());
  for (int c = 0; c < 2; ++c) {
    EXPECT_EQ(lut.tables.channels[c].x_lo, one.texels[0][c]);
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
  expect_monotone_with_exact_slopes(t, "nearly constant");
  EXPECT_EQ(t.x_lo, t.x_hi);
  for (float s : t.forward_slope) ASSERT_EQ(s, 0.0f);
  EXPECT_LE(lut.statistics[0].round_trip_error, kFlatChannelSpread);
  // A spread of 1e-6 is not flat: real tables, finite slopes.
  for (int i = 0; i < 4; ++i) map.texels[i][0] = 0.1f + 1e-6f * float(i);
  const BakedLut fine = bake_standardization_lut(map, kLutDefaultSize, Progress::silent());
  EXPECT_LT(fine.tables.channels[0].x_lo, fine.tables.channels[0].x_hi);
  expect_monotone_with_exact_slopes(fine.tables.channels[0], "1e-6 spread");
}

TEST(StandardizationLut, SizeOutOfRangeIsRefused) {
  const NormalMap map = map_of(2, 2, [](uint32_t x, uint32_t) { return Vec3f(0.1f * x, 0, 1); });
  EXPECT_THROW(bake_standardization_lut(map, 1, Progress::silent()), Error);
  EXPECT_THROW(bake_standardization_lut(map, kLutMaxSize + 1, Progress::silent()), Error);
  EXPECT_NO_THROW(bake_standardization_lut(map, kLutMaxSize, Progress::silent()));
}

}  // namespace
}  // namespace mbk
