// Order-2 SH lighting: the basis is orthonormal; projecting lat-long maps of known functions gives their
// closed-form coefficients; irradiance equals the brute-force cosine-weighted integral for band-limited
// lighting; the vMF band factors equal the numerical Legendre projection of the lobe; skies are constant.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "formats/error.h"
#include "libbake/eval/sh_lighting.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

// Numerical integral over the sphere of f(d) (theta, phi midpoint grid).
template <typename F>
auto sphere_integral(F f, int nt = 400, int np = 800) {
  using Value = decltype(f(Vec3::UnitZ()));  // an Eigen vector or matrix
  Value sum = Value::Zero();
  for (int i = 0; i < nt; ++i) {
    const double t = (i + 0.5) * kPi / nt;
    for (int j = 0; j < np; ++j) sum += f(lat_long_direction((j + 0.5) * 2 * kPi / np, t)) * std::sin(t);
  }
  return Value(sum * ((kPi / nt) * (2 * kPi / np)));
}

Image lat_long_map(uint32_t w, uint32_t h, const std::function<Vec3(const Vec3&)>& radiance) {
  Image m;
  m.width = w;
  m.height = h;
  m.channels = 3;
  m.pixels.resize(size_t(w) * h * 3);
  for (uint32_t row = 0; row < h; ++row)
    for (uint32_t i = 0; i < w; ++i) {
      const Vec3 L = radiance(lat_long_direction(2 * kPi * (i + 0.5) / w, kPi * (row + 0.5) / h));
      for (uint32_t c = 0; c < 3; ++c) m.at(i, row, c) = float(L[c]);
    }
  return m;
}

TEST(ShLighting, BasisIsOrthonormal) {
  using Gram = Eigen::Matrix<double, kShCount, kShCount>;
  const Gram g = sphere_integral([](const Vec3& d) {
    const ShBasis y = sh_basis(d);
    const Eigen::Map<const Eigen::Matrix<double, kShCount, 1>> v(y.data());
    return Gram(v * v.transpose());
  });
  for (int a = 0; a < kShCount; ++a)
    for (int b = 0; b < kShCount; ++b) EXPECT_NEAR(g(a, b), a == b ? 1.0 : 0.0, 1e-4) << a << "," << b;
}

TEST(ShLighting, LatLongRowZeroIsTheZenith) {
  EXPECT_LT((lat_long_direction(0.3, 0.0) - Vec3::UnitY()).norm(), 1e-15);
  EXPECT_LT((lat_long_direction(kPi, kPi / 2) + Vec3::UnitX()).norm(), 1e-15);  // the centre column faces -X
}

TEST(ShLighting, ProjectsAClampedCosineMapToItsClosedForm) {
  // L(d) = max(0, d_z): L00 = sqrt(pi)/2, L10 = sqrt(pi/3), L20 = sqrt(5 pi)/8, all others 0
  // [Ramamoorthi & Hanrahan 2001, the clamped cosine's expansion].
  const ShCoefficients sh =
      project_lat_long(lat_long_map(512, 256, [](const Vec3& d) { return Vec3::Constant(std::max(0.0, d.z())); }));
  const double expected[kShCount] = {std::sqrt(kPi) / 2, 0, std::sqrt(kPi / 3), 0, 0, 0, std::sqrt(5 * kPi) / 8, 0, 0};
  for (int k = 0; k < kShCount; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sh[k][c], expected[k], 2e-3) << "coefficient " << k;
}

TEST(ShLighting, ProjectsAConstantMapExactly) {
  const ShCoefficients sh = project_lat_long(lat_long_map(7, 5, [](const Vec3&) { return Vec3(1.0, 2.0, 0.5); }));
  // The texels' exact solid angles sum to 4 pi, so L00 = 2 sqrt(pi) L even on a 7 x 5 map.
  EXPECT_LT((sh[0] - 2 * std::sqrt(kPi) * Vec3(1.0, 2.0, 0.5)).norm(), 1e-12);
  EXPECT_LT((sh[0] - constant_radiance_sh(Vec3(1.0, 2.0, 0.5))[0]).norm(), 1e-12);
}

TEST(ShLighting, IrradianceIsTheExactCosineConvolutionOfBandLimitedLight) {
  // L is a polynomial of degree 2 in d: its projection to order 2 is exact, and so must be E(n).
  auto L = [](const Vec3& d) {
    return Vec3(1.0 + 0.8 * d.z() + 0.3 * d.x() * d.y(), 0.5 + 0.4 * d.x() * d.x(), 0.7 - 0.6 * d.y());
  };
  const ShCoefficients sh = project_lat_long(lat_long_map(512, 256, L));
  for (const Vec3& n :
       {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.3, -0.5, 0.81).normalized(), Vec3(-0.7, 0.7, -0.1).normalized()}) {
    const Vec3 brute = sphere_integral([&](const Vec3& w) { return Vec3(L(w) * std::max(0.0, n.dot(w))); });
    EXPECT_LT((sh_irradiance(sh, n) - brute).norm(), 2e-3)
        << n.transpose() << ": " << sh_irradiance(sh, n).transpose() << " vs " << brute.transpose();
    EXPECT_LT((sh_radiance(sh, n) - L(n)).norm(), 1e-3);  // band-limited: reconstructed exactly
  }
}

TEST(ShLighting, VmfBandFactorsMatchTheLobesLegendreProjection) {
  // Lambda_l = 2 pi * integral over t in [-1, 1] of vMF(t) P_l(t), vMF(t) = k / (2 pi (1 - exp(-2k))) exp(k (t - 1)).
  for (double kappa : {0.01, 0.09, 0.11, 0.5, 2.0, 20.0, 500.0}) {
    const int n = 400000;
    double l0 = 0, l1 = 0, l2 = 0;
    for (int i = 0; i < n; ++i) {
      const double t = -1 + (i + 0.5) * 2.0 / n;
      const double f = kappa / (2 * kPi * -std::expm1(-2 * kappa)) * std::exp(kappa * (t - 1)) * 2 * kPi * (2.0 / n);
      l0 += f;
      l1 += f * t;
      l2 += f * 0.5 * (3 * t * t - 1);
    }
    const auto lambda = vmf_band_factors(kappa);
    EXPECT_NEAR(lambda[0], l0, 1e-6) << kappa;
    EXPECT_NEAR(lambda[1], l1, 1e-6) << kappa;
    EXPECT_NEAR(lambda[2], l2, 1e-6) << kappa;
  }
  // Continuity where the series hands over to the closed form.
  const auto below = vmf_band_factors(0.1 - 1e-12), above = vmf_band_factors(0.1 + 1e-12);
  EXPECT_NEAR(below[1], above[1], 1e-11);
  EXPECT_NEAR(below[2], above[2], 1e-11);
  EXPECT_TRUE(std::isfinite(vmf_band_factors(specular_lobe_kappa(0.001))[2]));
}

TEST(ShLighting, UniformSkyGivesPiRadianceIrradianceEverywhere) {
  const Vec3 L(0.2, 0.3, 0.4);
  const ShCoefficients sh = constant_radiance_sh(L);
  for (const Vec3& d : {Vec3(0, 1, 0), Vec3(0.6, -0.8, 0), Vec3(0, 0, -1)}) {
    EXPECT_LT((sh_irradiance(sh, d) - kPi * L).norm(), 1e-14);
    EXPECT_LT((sh_radiance(sh, d) - L).norm(), 1e-14);
    EXPECT_LT((sh_lobe_radiance(sh, d, 3.0) - L).norm(), 1e-14);  // a normalised lobe of a constant is the constant
  }
}

TEST(ShLighting, NonFiniteEnvironmentTexelIsInvalidInput) {
  Image m = lat_long_map(8, 4, [](const Vec3&) { return Vec3::Ones(); });
  m.at(3, 2, 1) = NAN;
  EXPECT_THROW(project_lat_long(m), Error);
}

}  // namespace
}  // namespace mbk
