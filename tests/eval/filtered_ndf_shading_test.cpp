// Shading with filtered NDFs (libbake/eval/filtered_ndf_shading.h) against numerical integration of the NDF
// times the BRDF: exact for SH when the BRDF is a polynomial within the order, converging for Blinn-Phong;
// Eq. 7.14 with exact Bessel factors against quadrature over a vMF lobe; the closed forms 7.20/7.21 and
// Toksvig as approximations (and where Toksvig loses: two-lobed NDFs); SH lighting 7.23 against quadrature;
// and filtered shading at the finest level equal to unfiltered shading.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "libbake/core/gauss_legendre.h"
#include "libbake/eval/filtered_ndf_shading.h"
#include "libbake/eval/sh_lighting.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

Vec3 direction(double theta_deg, double phi_deg) {
  const double t = theta_deg * kPi / 180, p = phi_deg * kPi / 180;
  return Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

std::vector<Vec3> random_normals(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 0.5);
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) out.push_back(Vec3(g(rng), g(rng), 1.0).normalized());
  return out;
}

std::vector<double> mean_coefficients(const ShBasisEvaluator& basis, const std::vector<Vec3>& normals) {
  std::vector<double> g(size_t(basis.count()), 0.0), y(g.size());
  for (const Vec3& n : normals) {
    delta_ndf_coefficients(basis, n, y);
    for (size_t k = 0; k < g.size(); ++k) g[k] += y[k] / double(normals.size());
  }
  return g;
}

// integral over the sphere of f(w . n) vMF(n; kappa, mu) dn, in a frame around mu (Gauss-Legendre in the cosine
// over where the lobe lives, uniform in azimuth).
double integrate_over_vmf(const std::function<double(double)>& f, double kappa, const Vec3& mu, const Vec3& w) {
  const double width = std::min(2.0, 60.0 / kappa);
  const std::vector<QuadratureNode> rule = composite_gauss_legendre(1.0 - width, 1.0, 1, 300);
  const Vec3 a = std::abs(mu.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 t = mu.cross(a).normalized(), b = mu.cross(t);
  constexpr int kSteps = 720;
  double sum = 0.0;
  for (size_t i = 0; i < rule.size(); ++i) {
    const double c = rule[i].x, s = std::sqrt(std::max(0.0, 1 - c * c));
    const double density = std::exp(vmf_log_density(kappa, c));
    for (int j = 0; j < kSteps; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / kSteps;
      const Vec3 n = c * mu + s * (std::cos(phi) * t + std::sin(phi) * b);
      sum += rule[i].w * (2 * kPi / kSteps) * density * f(w.dot(n));
    }
  }
  return sum;
}

TEST(FilteredNdfShading, ZonalCoefficientsOfLambertAreRamamoorthiHanrahan) {
  const auto rhat = zonal_brdf_coefficients([](double t) { return std::max(t, 0.0); }, 4);
  EXPECT_NEAR(rhat[0], kPi, 1e-13);
  EXPECT_NEAR(rhat[1], 2 * kPi / 3, 1e-13);
  EXPECT_NEAR(rhat[2], kPi / 4, 1e-13);
  EXPECT_NEAR(rhat[3], 0.0, 1e-13);
  EXPECT_NEAR(rhat[4], -kPi / 24, 1e-13);
}

// A BRDF that is a polynomial of degree <= L in t has an exact order-L expansion, so Eq. 7.12 must equal the
// brute-force mean of f(w . n_i) over the texel's normals to rounding.
TEST(FilteredNdfShading, ShEqualsBruteForceForPolynomialBrdf) {
  constexpr int L = 6;
  auto f = [](double t) { return std::pow(1 + t, 6) / 64; };
  const auto rhat = zonal_brdf_coefficients(f, L);
  const ShBasisEvaluator basis(L);
  const auto normals = random_normals(37, 3);
  const auto g = mean_coefficients(basis, normals);
  const std::vector<double> window(L + 1, 1.0);
  for (const Vec3& w : {direction(0, 0), direction(35, 80), direction(70, 200), direction(120, 10)}) {
    double brute = 0.0;
    for (const Vec3& n : normals) brute += f(w.dot(n)) / double(normals.size());
    EXPECT_NEAR(sh_filtered_brdf(basis, g, window, rhat, w), brute, 1e-12);
  }
}

// Truncation error of a non-polynomial lobe, RMS over directions: not monotone at every direction (ringing),
// but falling with the order overall and small at order 64 for exponent 10 (the paper's l* ~ sqrt(4 s) = 6.3
// is the low-accuracy end).
TEST(FilteredNdfShading, ShBlinnPhongConvergesWithOrder) {
  const double s = 10;
  auto f = [&](double t) { return blinn_phong_lobe(s, t); };
  const auto normals = random_normals(50, 8);
  std::vector<Vec3> ws;
  for (int i = 0; i < 40; ++i) ws.push_back(direction(2.0 * i, 37.0 * i));
  std::vector<double> rms;
  for (int order : {4, 8, 16, 32, 64}) {
    const ShBasisEvaluator basis(order);
    const auto g = mean_coefficients(basis, normals);
    const std::vector<double> window(size_t(order) + 1, 1.0);
    const auto rhat = zonal_brdf_coefficients(f, order);
    double sum = 0.0;
    for (const Vec3& w : ws) {
      double brute = 0.0;
      for (const Vec3& n : normals) brute += f(w.dot(n)) / double(normals.size());
      sum += std::pow(sh_filtered_brdf(basis, g, window, rhat, w) - brute, 2);
    }
    rms.push_back(std::sqrt(sum / double(ws.size())));
  }
  for (size_t i = 1; i < rms.size(); ++i) EXPECT_LT(rms[i], rms[i - 1]) << i;
  EXPECT_LT(rms.back(), 1e-3 * (s + 1) / (2 * kPi));
}

TEST(FilteredNdfShading, VmfEquation714MatchesNumericalIntegration) {
  const double s = 20;
  auto f = [&](double t) { return blinn_phong_lobe(s, t); };
  const auto rhat = zonal_brdf_coefficients(f, 80);
  for (double kappa : {2.0, 30.0, 400.0}) {
    const VmfLobeShape lobe{1.0, kappa, direction(20, 30)};
    for (const Vec3& w : {direction(20, 30), direction(35, 60), direction(60, 200)}) {
      const double exact = integrate_over_vmf(f, kappa, lobe.mu, w);
      EXPECT_NEAR(vmf_filtered_brdf(std::span(&lobe, 1), rhat, w), exact, 1e-6 * (s + 1) / (2 * kPi))
          << "kappa " << kappa;
    }
  }
}

// Eq. 7.20 is an approximation (Gaussian lobes on the tangent plane): good near the peak for sharp lobes.
TEST(FilteredNdfShading, BlinnPhongClosedFormIsCloseForSharpLobes) {
  const double s = 50, kappa = 200;
  const Vec3 mu = direction(10, 0);
  auto f = [&](double t) { return blinn_phong_lobe(s, t); };
  const double exact = integrate_over_vmf(f, kappa, mu, mu);
  const double closed = blinn_phong_lobe(vmf_filtered_blinn_phong_exponent(s, kappa), 1.0);
  EXPECT_NEAR(closed, exact, 0.03 * exact);
}

// Eq. 7.21 in Beckmann alpha against integrating the Beckmann NDF over a vMF lobe of normals, near the peak.
TEST(FilteredNdfShading, BeckmannClosedFormIsCloseForSharpLobes) {
  const double alpha = 0.15, kappa = 150;
  auto beckmann = [&](double alpha_, double t) {
    if (t <= 0) return 0.0;
    const double t2 = t * t;
    return std::exp(-(1 - t2) / (t2 * alpha_ * alpha_)) / (kPi * alpha_ * alpha_ * t2 * t2);
  };
  const Vec3 mu = direction(5, 0);
  for (double off : {0.0, 4.0, 8.0}) {
    const Vec3 w = direction(5 + off, 0);
    const double exact = integrate_over_vmf([&](double t) { return beckmann(alpha, t); }, kappa, mu, w);
    const double closed = beckmann(vmf_filtered_beckmann_alpha(alpha, kappa), w.dot(mu));
    EXPECT_NEAR(closed, exact, 0.05 * exact) << off;
  }
}

TEST(FilteredNdfShading, FinestLevelEqualsUnfilteredShading) {
  const Vec3 n = direction(25, 70), w = direction(30, 60);
  // A finest vMF texel is (1, n): kappa at the cap.
  const VmfLobeShape lobe = vmf_lobe_from_premultiplied(1.0, n, 1e6);
  EXPECT_EQ(lobe.kappa, 1e6);
  const double s = 40;
  EXPECT_NEAR(blinn_phong_lobe(vmf_filtered_blinn_phong_exponent(s, lobe.kappa), w.dot(lobe.mu)),
              blinn_phong_lobe(s, w.dot(n)), 1e-4 * blinn_phong_lobe(s, w.dot(n)));
  EXPECT_NEAR(vmf_filtered_beckmann_alpha(0.2, lobe.kappa), 0.2, 1e-4);
  EXPECT_EQ(toksvig_beckmann_alpha(0.2, 1.0), 0.2);
  // SH: the finest level's coefficients Y_lm(n) shade a polynomial BRDF exactly like the normal itself.
  const ShBasisEvaluator basis(6);
  std::vector<double> g(size_t(basis.count()));
  delta_ndf_coefficients(basis, n, g);
  auto f = [](double t) { return std::pow(1 + t, 6) / 64; };
  EXPECT_NEAR(sh_filtered_brdf(basis, g, std::vector<double>(7, 1.0), zonal_brdf_coefficients(f, 6), w), f(w.dot(n)),
              1e-13);
}

// For a single vMF lobe Toksvig (from the mean length) and Eq. 7.21 agree; for a V-groove's two facets the
// mean normal points between them and Toksvig's one broad lobe misses both peaks, which the mixture keeps.
TEST(FilteredNdfShading, ToksvigAgreesForOneLobeLosesTwoLobes) {
  for (double kappa : {50.0, 500.0}) {
    EXPECT_NEAR(toksvig_beckmann_alpha(0.1, vmf_mean_length(kappa)), vmf_filtered_beckmann_alpha(0.1, kappa),
                0.02 * vmf_filtered_beckmann_alpha(0.1, kappa));
  }
  const double s = 200;
  const Vec3 a = direction(20, 0), b = direction(20, 180), w = a;
  const double truth = 0.5 * blinn_phong_lobe(s, w.dot(a)) + 0.5 * blinn_phong_lobe(s, w.dot(b));
  const double mixture = 0.5 * blinn_phong_lobe(vmf_filtered_blinn_phong_exponent(s, 1e6), w.dot(a)) +
                         0.5 * blinn_phong_lobe(vmf_filtered_blinn_phong_exponent(s, 1e6), w.dot(b));
  const Vec3 mean = 0.5 * (a + b);
  const double toksvig = blinn_phong_lobe(toksvig_blinn_phong_exponent(s, mean.norm()), w.dot(mean.normalized()));
  EXPECT_LT(std::abs(mixture - truth), 1e-3 * truth);
  EXPECT_GT(std::abs(toksvig - truth), 0.5 * truth);
}

// Eq. 7.23 is exact: the filtered irradiance equals integrating the (unclamped) SH irradiance over the lobe.
TEST(FilteredNdfShading, VmfShLightingMatchesQuadratureAndIrradianceAtTheCap) {
  const std::vector<double> light = {1.2, 0.3, 0.8, -0.2, 0.1, 0.05, -0.3, 0.2, 0.15};
  const auto rhat = zonal_brdf_coefficients([](double t) { return std::max(t, 0.0); }, 2);
  const ShBasisEvaluator basis(2);
  auto irradiance = [&](const Vec3& n) {
    std::vector<double> y(9);
    basis.evaluate(n, y);
    double e = 0;
    for (int k = 0; k < 9; ++k) e += rhat[size_t(k == 0 ? 0 : k < 4 ? 1 : 2)] * light[size_t(k)] * y[size_t(k)];
    return e;
  };
  const Vec3 mu = direction(30, 45);
  for (double kappa : {1.0, 10.0, 100.0}) {
    // The integrand depends on n itself (not only on w . n), so integrate directly around mu.
    const double width = std::min(2.0, 60.0 / kappa);
    const std::vector<QuadratureNode> rule = composite_gauss_legendre(1.0 - width, 1.0, 1, 100);
    const Vec3 t = mu.cross(Vec3::UnitX()).normalized(), b = mu.cross(t);
    double sum = 0;
    for (size_t i = 0; i < rule.size(); ++i)
      for (int j = 0; j < 64; ++j) {
        const double c = rule[i].x, s = std::sqrt(1 - c * c), phi = 2 * kPi * (j + 0.5) / 64;
        sum += rule[i].w * (2 * kPi / 64) * std::exp(vmf_log_density(kappa, c)) *
               irradiance(c * mu + s * (std::cos(phi) * t + std::sin(phi) * b));
      }
    EXPECT_NEAR(vmf_sh_lighting(light, rhat, kappa, mu), sum, 1e-10) << kappa;
  }
  ShCoefficients rgb;
  for (int k = 0; k < 9; ++k) rgb[size_t(k)] = Vec3::Constant(light[size_t(k)]);
  EXPECT_NEAR(vmf_sh_lighting(light, rhat, INFINITY, mu), sh_irradiance(rgb, mu).x(), 1e-12);
}

}  // namespace
}  // namespace mbk
