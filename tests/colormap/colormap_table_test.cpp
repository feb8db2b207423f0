// The prefiltered colour-map table (libbake/colormap/colormap_table.h, formats/colormap_layout.h): the sigma = 0
// row is C itself; every entry matches E[C(m + sigma Z)] by independent numerical quadrature
// (tests/colormap/colormap_quadrature.h), on tiny and on the paper's 256 x 256 size with a 256-knot gradient;
// hard cases (one knot, hard edges, sigma far beyond the domain, tiny sigma, mean outside the domain) by name;
// the bake passes validate and is byte-identical whatever the thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/asset.h"
#include "formats/colormap_layout.h"
#include "formats/validate.h"
#include "libbake/colormap/colormap_table.h"
#include "libbake/core/parallel.h"
#include "tests/colormap/colormap_quadrature.h"

namespace mbk {
namespace {

// Non-uniform knots, a steep segment, a hard edge at 0.6 and colours beyond [0, 1] (HDR).
ColormapCurve banded_curve() {
  ColormapCurve c;
  c.knots = {0.1, 0.3, 0.32, 0.6, 0.6, 0.85};
  c.colors = {{0.05, 0.1, 0.8}, {0.9, 0.2, 0.1}, {0.1, 0.9, 0.2}, {0.7, 0.7, 0.0}, {0.0, 0.0, 0.0}, {2.5, 1.5, 0.5}};
  return c;
}

// A 256-texel gradient with wiggles, as an image would give: knots at texel centres.
ColormapCurve gradient_curve(uint32_t texels) {
  ColormapCurve c;
  for (uint32_t x = 0; x < texels; ++x) {
    const double u = (x + 0.5) / texels;
    c.knots.push_back(u);
    c.colors.push_back({0.5 + 0.5 * std::sin(19.0 * u), u * u, std::abs(std::cos(7.0 * u + 0.3 * std::sin(40.0 * u)))});
  }
  return c;
}

test::PiecewiseLinearMap reference_of(const ColormapCurve& c) { return {c.knots, c.colors}; }

ColormapTableOptions options(uint32_t w, uint32_t h, double lo, double hi, double sigma_max) {
  ColormapTableOptions o;
  o.width = w, o.height = h, o.mean_min = lo, o.mean_max = hi, o.sigma_max = sigma_max;
  return o;
}

double entry(const ColormapTable& t, uint32_t j, uint32_t i, int c) {
  return t.values[(size_t(j) * t.width + i) * 3 + c];
}

TEST(ColormapTable, SigmaZeroRowEqualsC) {
  const ColormapCurve curve = banded_curve();
  const BakedColormap b = bake_colormap_table(curve, options(101, 5, 0.0, 1.0, 0.5), Progress::silent());
  const auto ref = reference_of(b.curve);
  for (uint32_t i = 0; i < b.table.width; ++i) {
    const auto c = ref(b.table.mean_at(i));
    for (int k = 0; k < 3; ++k) EXPECT_EQ(entry(b.table, 0, i, k), float(c[k])) << "column " << i;
  }
}

TEST(ColormapTable, EntriesMatchIndependentQuadrature_Small) {
  const BakedColormap b = bake_colormap_table(banded_curve(), options(37, 23, -0.2, 1.1, 0.4), Progress::silent());
  const auto ref = reference_of(b.curve);
  for (uint32_t j = 0; j < b.table.height; ++j)
    for (uint32_t i = 0; i < b.table.width; ++i) {
      const auto q = test::gaussian_average_by_quadrature(ref, b.table.mean_at(i), b.table.sigma_at(j));
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(entry(b.table, j, i, k), q[k], 1e-6 * 2.5) << "row " << j << " column " << i << " channel " << k;
    }
}

TEST(ColormapTable, EntriesMatchIndependentQuadrature_PaperSize256Knots) {
  const BakedColormap b =
      bake_colormap_table(gradient_curve(256), options(256, 256, 0.0, 1.0, 0.0), Progress::silent());
  EXPECT_EQ(b.table.sigma_max, float(0.5));  // the default: half the domain
  const auto ref = reference_of(b.curve);
  // Every 7th column of every 5th row, plus the last row and column: ~2000 entries.
  auto every = [](uint32_t step) {
    std::vector<uint32_t> v;
    for (uint32_t n = 0; n < 255; n += step) v.push_back(n);
    v.push_back(255);
    return v;
  };
  for (uint32_t j : every(5))
    for (uint32_t i : every(7)) {
      const auto q = test::gaussian_average_by_quadrature(ref, b.table.mean_at(i), b.table.sigma_at(j));
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(entry(b.table, j, i, k), q[k], 1e-6) << "row " << j << " column " << i;
    }
}

TEST(ColormapTable, LookupReturnsEntriesAtSamplesAndInterpolatesBetween) {
  const BakedColormap b = bake_colormap_table(banded_curve(), options(9, 7, 0.0, 1.0, 0.3), Progress::silent());
  const ColormapTable& t = b.table;
  for (uint32_t j = 0; j < t.height; ++j)
    for (uint32_t i = 0; i < t.width; ++i) {
      const auto v = t.lookup(t.mean_at(i), t.sigma_at(j));
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[k], entry(t, j, i, k), 1e-12);
    }
  const auto mid = t.lookup(0.5 * (t.mean_at(2) + t.mean_at(3)), 0.5 * (t.sigma_at(4) + t.sigma_at(5)));
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(mid[k], 0.25 * (entry(t, 4, 2, k) + entry(t, 4, 3, k) + entry(t, 5, 2, k) + entry(t, 5, 3, k)), 1e-7);
  // Clamped outside the table; NaN in, NaN out.
  const auto below = t.lookup(-5.0, -1.0), above = t.lookup(7.0, 9.0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(below[k], entry(t, 0, 0, k));
    EXPECT_DOUBLE_EQ(above[k], entry(t, t.height - 1, t.width - 1, k));
  }
  EXPECT_TRUE(std::isnan(t.lookup(std::nan(""), 0.1)[0]));
}

TEST(ColormapTable, LookupErrorStatisticIsTheWorstCellCentre) {
  const BakedColormap b = bake_colormap_table(banded_curve(), options(17, 9, 0.0, 1.0, 0.3), Progress::silent());
  const ColormapTable& t = b.table;
  const auto ref = reference_of(b.curve);
  double worst = 0.0;
  for (uint32_t j = 0; j + 1 < t.height; ++j)
    for (uint32_t i = 0; i + 1 < t.width; ++i) {
      const double m = 0.5 * (t.mean_at(i) + t.mean_at(i + 1)), s = 0.5 * (t.sigma_at(j) + t.sigma_at(j + 1));
      const auto q = test::gaussian_average_by_quadrature(ref, m, s);
      const auto v = t.lookup(m, s);
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(v[k] - q[k]));
    }
  EXPECT_NEAR(b.statistics.lookup_max_error, worst, 1e-6);
  EXPECT_GT(b.statistics.lookup_max_error, 1e-3);  // a hard edge on a 17-column table is coarse
  // Larger tables cost less error on average; the maximum stays at about half the hard edge's jump (the column
  // straddling it at sigma ~ 0, where the exact value is discontinuous and no table size resolves it).
  const BakedColormap fine = bake_colormap_table(banded_curve(), options(257, 129, 0.0, 1.0, 0.3), Progress::silent());
  EXPECT_LT(fine.statistics.lookup_rms_error, 0.25 * b.statistics.lookup_rms_error);
}

TEST(ColormapTable, HardEdgeAveragesItsTwoColoursAtTheEdge) {
  ColormapCurve c;
  c.knots = {0.5, 0.5};
  c.colors = {{0.0, 0.2, 1.0}, {1.0, 0.6, 0.0}};
  for (double sigma : {1e-3, 0.1, 3.0}) {
    const auto v = c.convolved(0.5, sigma);
    EXPECT_DOUBLE_EQ(v[0], 0.5);
    EXPECT_DOUBLE_EQ(v[1], 0.4);
  }
  EXPECT_EQ(c.at(0.5)[0], 1.0);  // right-continuous
  EXPECT_EQ(c.at(std::nextafter(0.5, 0.0))[0], 0.0);
}

TEST(ColormapTable, SingleKnotIsConstant) {
  ColormapCurve c;
  c.knots = {0.3};
  c.colors = {{0.2, 0.4, 0.6}};
  const BakedColormap b = bake_colormap_table(c, options(4, 3, 0.0, 1.0, 2.0), Progress::silent());
  for (size_t n = 0; n < b.table.values.size(); ++n) EXPECT_EQ(b.table.values[n], float(c.colors[0][n % 3]));
  EXPECT_EQ(b.statistics.naive_max_error, 0.0);
}

TEST(ColormapTable, HugeSigmaTendsToTheMeanOfTheEndColours) {
  // With clamp extension, half the mass of a very wide Gaussian lands on each end colour.
  const ColormapCurve c = banded_curve();
  const auto v = c.convolved(0.5, 1e6);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[k], 0.5 * (c.colors.front()[k] + c.colors.back()[k]), 1e-6);
}

TEST(ColormapTable, TinySigmaIsCWithoutUnderflow) {
  const ColormapCurve c = banded_curve();
  for (double m : {0.0, 0.31, 0.600001, 0.599999, 0.9})  // (at the edge itself the mean of both sides)
    for (double sigma : {1e-300, 1e-20, 1e-12}) {
      const auto v = c.convolved(m, sigma), exact = c.at(m);
      for (int k = 0; k < 3; ++k) {
        ASSERT_TRUE(std::isfinite(v[k]));
        EXPECT_NEAR(v[k], exact[k], 1e-9) << m << " " << sigma;
      }
    }
}

TEST(ColormapTable, MeanOutsideTheKnotsSeesTheClampedEnds) {
  const ColormapCurve c = banded_curve();
  const auto ref = reference_of(c);
  for (double m : {-3.0, 4.0})
    for (double sigma : {0.05, 0.5, 2.0}) {
      const auto v = c.convolved(m, sigma), q = test::gaussian_average_by_quadrature(ref, m, sigma);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[k], q[k], 1e-9);
    }
}

TEST(ColormapTable, RejectsBadSizesAndSigma) {
  const ColormapCurve c = banded_curve();
  EXPECT_THROW(bake_colormap_table(c, options(1, 256, 0, 1, 0), Progress::silent()), Error);
  EXPECT_THROW(bake_colormap_table(c, options(256, 8193, 0, 1, 0), Progress::silent()), Error);
  EXPECT_THROW(bake_colormap_table(c, options(8, 8, 1, 1, 0), Progress::silent()), Error);
  EXPECT_THROW(bake_colormap_table(c, options(8, 8, 0, 1, -1), Progress::silent()), Error);
  EXPECT_THROW(bake_colormap_table(c, options(8, 8, 0, 1, std::nan("")), Progress::silent()), Error);
  ColormapCurve three_at_one_place = c;
  three_at_one_place.knots = {0.1, 0.3, 0.3, 0.3, 0.6, 0.85};
  EXPECT_THROW(bake_colormap_table(three_at_one_place, options(8, 8, 0, 1, 0), Progress::silent()), Error);
}

std::vector<uint8_t> asset_bytes(const ColormapCurve& c, const ColormapTableOptions& o) {
  return colormap_asset_writer(bake_colormap_table(c, o, Progress::silent()), {{"path", "in-memory"}}, "linear")
      .serialize();
}

TEST(ColormapAsset, PassesValidationAndReadsBack) {
  for (const auto& [curve, o] : {std::pair{banded_curve(), options(37, 23, -0.2, 1.1, 0.4)},
                                 {gradient_curve(256), options(256, 256, 0.0, 1.0, 0.0)},
                                 {gradient_curve(1), options(2, 2, 0.0, 1.0, 0.0)}}) {
    const std::vector<uint8_t> bytes = asset_bytes(curve, o);
    for (const Finding& f : validate_asset(bytes)) ADD_FAILURE() << f.id << " " << f.message;
    const Asset a = Asset::parse(bytes, "test");
    const ColormapTable t = read_colormap_table(a);
    const BakedColormap b = bake_colormap_table(curve, o, Progress::silent());
    EXPECT_EQ(t.values, b.table.values);
    EXPECT_EQ(t.sigma_max, b.table.sigma_max);
    EXPECT_EQ(a.metadata()["statistics"]["lookup_max_error"].get<double>(), b.statistics.lookup_max_error);
  }
}

TEST(ColormapAsset, SameBytesWhateverTheThreadCount) {
  const int before = thread_count();
  set_thread_count(1);
  const auto one = asset_bytes(gradient_curve(64), options(64, 32, 0.0, 1.0, 0.0));
  set_thread_count(3);
  const auto three = asset_bytes(gradient_curve(64), options(64, 32, 0.0, 1.0, 0.0));
  set_thread_count(before);
  EXPECT_EQ(one, three);
}

}  // namespace
}  // namespace mbk
