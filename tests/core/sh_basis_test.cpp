// Tests of the shared real SH basis (libbake/core/sh_basis.h): closed forms to band 3, orthonormality by
// exact quadrature, the addition theorem against independent Legendre polynomials to order 128, and finite,
// exact values at the poles and the equator at order 128.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "libbake/core/gauss_legendre.h"
#include "libbake/core/sh_basis.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

Vec3 random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 d(g(rng), g(rng), g(rng));
  return d.normalized();
}

// Legendre polynomial P_l(t) by Bonnet's recurrence (unnormalised), independent of the basis code.
double legendre(int l, double t) {
  double p0 = 1.0, p1 = t;
  if (l == 0) return 1.0;
  for (int k = 2; k <= l; ++k) {
    const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  return p1;
}

TEST(ShBasis, MatchesClosedFormsToBand3) {
  const ShBasisEvaluator basis(3);
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 d = random_direction(rng);
    const double x = d.x(), y = d.y(), z = d.z();
    const double expected[16] = {
        0.5 / std::sqrt(kPi),
        std::sqrt(3 / (4 * kPi)) * y,
        std::sqrt(3 / (4 * kPi)) * z,
        std::sqrt(3 / (4 * kPi)) * x,
        std::sqrt(15 / (4 * kPi)) * x * y,
        std::sqrt(15 / (4 * kPi)) * y * z,
        std::sqrt(5 / (16 * kPi)) * (3 * z * z - 1),
        std::sqrt(15 / (4 * kPi)) * x * z,
        std::sqrt(15 / (16 * kPi)) * (x * x - y * y),
        std::sqrt(35 / (32 * kPi)) * (3 * x * x - y * y) * y,
        std::sqrt(105 / (4 * kPi)) * x * y * z,
        std::sqrt(21 / (32 * kPi)) * y * (5 * z * z - 1),
        std::sqrt(7 / (16 * kPi)) * (5 * z * z * z - 3 * z),
        std::sqrt(21 / (32 * kPi)) * x * (5 * z * z - 1),
        std::sqrt(105 / (16 * kPi)) * (x * x - y * y) * z,
        std::sqrt(35 / (32 * kPi)) * (x * x - 3 * y * y) * x,
    };
    const auto values = basis.evaluate(d);
    for (int k = 0; k < 16; ++k) EXPECT_NEAR(values[size_t(k)], expected[k], 1e-14) << "k = " << k;
  }
}

// Gauss-Legendre in cos(theta) with n nodes and M uniform steps in phi integrates Y_lm Y_l'm' exactly for
// l, l' <= L when n > L and M > 2L. Values are kept per function (contiguous over the quadrature points), and
// the point weights are folded in as square roots, so an entry of the Gram matrix is one dot product.
struct SphereQuadrature {
  std::vector<std::vector<double>> by_function;  // sqrt(weight_q) Y_k(d_q)
  double entry(int a, int b) const {
    const auto &x = by_function[size_t(a)], &y = by_function[size_t(b)];
    double sum = 0.0;
    for (size_t q = 0; q < x.size(); ++q) sum += x[q] * y[q];
    return sum;
  }
};

SphereQuadrature sphere_quadrature(int order) {
  const std::vector<QuadratureNode> rule = gauss_legendre_nodes(order + 2);
  const int steps = 2 * order + 3;
  const ShBasisEvaluator basis(order);
  SphereQuadrature q;
  q.by_function.assign(size_t(basis.count()), {});
  std::vector<double> y(size_t(basis.count()));
  for (size_t i = 0; i < rule.size(); ++i)
    for (int j = 0; j < steps; ++j) {
      const double t = rule[i].x, s = std::sqrt(1 - t * t), phi = 2 * kPi * (j + 0.25) / steps;
      basis.evaluate(Vec3(s * std::cos(phi), s * std::sin(phi), t), y);
      const double root_weight = std::sqrt(rule[i].w * 2 * kPi / steps);
      for (size_t k = 0; k < y.size(); ++k) q.by_function[k].push_back(root_weight * y[k]);
    }
  return q;
}

TEST(ShBasis, OrthonormalToOrder16ByQuadrature) {
  const SphereQuadrature q = sphere_quadrature(16);
  for (int a = 0; a < sh_count(16); ++a)
    for (int b = 0; b <= a; ++b) EXPECT_NEAR(q.entry(a, b), a == b ? 1.0 : 0.0, 1e-12) << a << "," << b;
}

// Order 64: every pair with |m| = |m'| (the only ones the phi sum does not separate by itself), plus a sample
// of the others.
TEST(ShBasis, OrthonormalToOrder64ByQuadrature) {
  constexpr int L = 64;
  const SphereQuadrature q = sphere_quadrature(L);
  double worst = 0.0;
  for (int m = 0; m <= L; ++m)
    for (int l = m; l <= L; ++l)
      for (int l2 = m; l2 <= l; ++l2)
        for (int s : {1, -1})
          for (int s2 : {1, -1}) {
            if (m == 0 && (s < 0 || s2 < 0)) continue;
            const int a = sh_index(l, s * m), b = sh_index(l2, s2 * m);
            worst = std::max(worst, std::abs(q.entry(a, b) - (a == b ? 1.0 : 0.0)));
          }
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> pick(0, sh_count(L) - 1);
  for (int i = 0; i < 5000; ++i) {
    const int a = pick(rng), b = pick(rng);
    worst = std::max(worst, std::abs(q.entry(a, b) - (a == b ? 1.0 : 0.0)));
  }
  EXPECT_LT(worst, 1e-11);
}

// Addition theorem: sum_m Y_lm(a) Y_lm(b) = (2l + 1) / (4 pi) P_l(a.b), with P_l from Bonnet's recurrence.
TEST(ShBasis, AdditionTheoremToOrder128) {
  constexpr int L = 128;
  const ShBasisEvaluator basis(L);
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 a = random_direction(rng), b = trial == 0 ? a : random_direction(rng);
    const auto ya = basis.evaluate(a), yb = basis.evaluate(b);
    for (int l = 0; l <= L; ++l) {
      double sum = 0.0;
      for (int m = -l; m <= l; ++m) sum += ya[size_t(sh_index(l, m))] * yb[size_t(sh_index(l, m))];
      const double expected = (2 * l + 1) / (4 * kPi) * legendre(l, std::clamp(a.dot(b), -1.0, 1.0));
      EXPECT_NEAR(sum, expected, 1e-11 * (2 * l + 1)) << "l = " << l;
    }
  }
}

// At the poles only m = 0 survives, Y_l0 = (+-1)^l sqrt((2l+1)/(4 pi)); on the equator Y_l0 = sqrt((2l+1)/(4 pi))
// P_l(0), P_l(0) = (-1)^(l/2) (l-1)!!/l!! for even l (by its ratio recurrence) and 0 for odd l.
TEST(ShBasis, FiniteAndExactAtPolesAndEquatorToOrder128) {
  constexpr int L = 128;
  const ShBasisEvaluator basis(L);
  for (const Vec3& d : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(1e-300, 0, 1),
                        Vec3(1e-9, -1e-9, -1).normalized()}) {
    const auto y = basis.evaluate(d);
    for (int l = 0; l <= L; ++l)
      for (int m = -l; m <= l; ++m) {
        const double v = y[size_t(sh_index(l, m))];
        ASSERT_TRUE(std::isfinite(v)) << l << " " << m;
        EXPECT_LE(std::abs(v), std::sqrt((2 * l + 1) / (2 * kPi)) + 1e-12);
      }
    if (d.x() == 0.0 && d.y() == 0.0)
      for (int l = 0; l <= L; ++l)
        for (int m = -l; m <= l; ++m) {
          const double expected = m != 0 ? 0.0 : std::pow(d.z(), l) * std::sqrt((2 * l + 1) / (4 * kPi));
          EXPECT_NEAR(y[size_t(sh_index(l, m))], expected, 1e-12 * (2 * l + 1));
        }
    if (d.z() == 0.0) {
      double p = 1.0;  // P_l(0) for even l
      for (int l = 0; l <= L; l += 2) {
        if (l > 0) p *= -double(l - 1) / l;
        EXPECT_NEAR(y[size_t(sh_index(l, 0))], std::sqrt((2 * l + 1) / (4 * kPi)) * p, 1e-13);
        if (l + 1 <= L) {
          EXPECT_NEAR(y[size_t(sh_index(l + 1, 0))], 0.0, 1e-13);
        }
      }
    }
  }
}

TEST(ShBasis, ZonalHarmonicsAreTheMZeroColumn) {
  constexpr int L = 128;
  const ShBasisEvaluator basis(L);
  std::vector<double> zonal(L + 1);
  for (double t : {-1.0, -0.3, 0.0, 0.7, 1.0}) {
    const double s = std::sqrt(1 - t * t);
    const auto y = basis.evaluate(Vec3(s * 0.6, s * 0.8, t));
    zonal_harmonics(L, t, zonal);
    for (int l = 0; l <= L; ++l) EXPECT_NEAR(zonal[size_t(l)], y[size_t(sh_index(l, 0))], 1e-13);
  }
}

}  // namespace
}  // namespace mbk
