// Hard cases of the vMF technique at both ends of kappa ([Han07] Sec. 7.6): spherical EM (libbake/filter/
// vmf_mixture.h) on antipodal, uniform and nearly identical normals, the pyramid on normals that cancel, and the
// shader's band factors Lambda_l(kappa) = I_{l+1/2}(kappa) / I_{1/2}(kappa) (libbake/core/vmf_lobe.h) and filtered
// BRDF (libbake/eval/filtered_ndf_shading.h) against the series and asymptotic expansions of the Bessel functions
// and against the closed forms of a uniform lobe and a delta.
// (Identical normals giving exactly the kappa cap: VmfMixture.IdenticalNormalsCapKappa; kappa = 0 and +inf in the
// band factors: VmfLobe.BandFactorsLimitsAndAsymptoticSwitch.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libbake/core/vmf_lobe.h"
#include "libbake/eval/filtered_ndf_shading.h"
#include "libbake/eval/lobe_specular.h"
#include "libbake/filter/vmf_mixture.h"
#include "libbake/filter/vmf_pyramid.h"
#include "tests/eval/lobe_mean.h"
#include "tests/hard_cases/hard_case_checks.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<VmfComponent> one_lobe_start(const Vec3& mu, double kappa) {
  std::vector<VmfComponent> mixture(1);
  mixture[0].alpha = 1.0, mixture[0].kappa = kappa, mixture[0].mu = mu;
  return mixture;
}

// Protects against: r = 0 exactly (normals that cancel) giving mu = 0 / 0 and kappa = A^-1(0) by a Newton step
// from 0: one lobe on two antipodal normals must be the uniform lobe, kappa 0 and log-likelihood -log(4 pi).
TEST(HardCases, VmfEmKappaToZeroOnAntipodalNormals) {
  const Vec3 n = Vec3(0.3, -0.5, 0.7).normalized();
  const std::vector<WeightedNormal> normals = {{n, 0.5}, {-n, 0.5}};
  std::vector<VmfComponent> mixture = one_lobe_start(n, 50.0);
  const EmReport report = fit_vmf_mixture(normals, mixture, EmOptions{});
  EXPECT_EQ(mixture[0].alpha, 1.0);
  EXPECT_EQ(mixture[0].r.norm(), 0.0);
  EXPECT_EQ(mixture[0].kappa, 0.0);
  EXPECT_NEAR(mixture[0].mu.norm(), 1.0, 1e-15);
  EXPECT_NEAR(report.log_likelihood, -std::log(4 * kPi), 1e-12);
}

// Protects against: the small-kappa end of A^-1 (A(k) = k / 3 - k^3 / 45 + ..., where coth(k) - 1/k cancels):
// normals spread evenly over the whole sphere (a Fibonacci lattice of 4000 points, |r| ~ 1e-4) must give
// kappa = A^-1(|r|) ~ 3 |r| and the uniform density's log-likelihood -log(4 pi) + kappa |r|.
TEST(HardCases, VmfEmKappaToZeroOnUniformNormals) {
  const int N = 4000;
  std::vector<WeightedNormal> normals;
  for (int i = 0; i < N; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / N, phi = i * kPi * (3.0 - std::sqrt(5.0)), s = std::sqrt(1 - z * z);
    normals.push_back({Vec3(s * std::cos(phi), s * std::sin(phi), z), 1.0 / N});
  }
  Vec3 mean = Vec3::Zero();
  for (const WeightedNormal& n : normals) mean += n.w * n.n;
  ASSERT_LT(mean.norm(), 1e-3);
  std::vector<VmfComponent> mixture = one_lobe_start(Vec3::UnitZ(), 20.0);
  const EmReport report = fit_vmf_mixture(normals, mixture, EmOptions{});
  EXPECT_NEAR(mixture[0].r.norm(), mean.norm(), 1e-15);
  EXPECT_NEAR(mixture[0].kappa, 3 * mean.norm(), 1e-6 * mean.norm());  // relative error ~ |r|^2
  EXPECT_NEAR(report.log_likelihood, -std::log(4 * kPi) + mixture[0].kappa * mean.norm(), 1e-9);
}

// Protects against: a jump between the Newton solve and the cap as normals become identical: for two normals an
// angle delta apart |r| = cos(delta / 2), and for kappa > 40 A(kappa) = 1 - 1/kappa to double precision, so kappa
// must be 1 / (1 - cos(delta / 2)) = 8 / delta^2 until that passes the cap (1e6), and the cap after.
TEST(HardCases, VmfEmKappaToInfinityOnNearlyIdenticalNormals) {
  for (const double delta : {3e-2, 1e-2, 3e-3, 2.8e-3, 1e-3, 1e-6}) {
    const Vec3 a(std::sin(delta / 2), 0, std::cos(delta / 2)), b(-std::sin(delta / 2), 0, std::cos(delta / 2));
    std::vector<VmfComponent> mixture = one_lobe_start(Vec3::UnitX(), 1.0);
    fit_vmf_mixture(std::vector<WeightedNormal>{{a, 0.5}, {b, 0.5}}, mixture, EmOptions{});
    const double expected = std::min(kVmfKappaMax, 1.0 / (1.0 - std::cos(delta / 2)));
    EXPECT_NEAR(mixture[0].kappa, expected, 1e-6 * expected) << delta;
    EXPECT_LT((mixture[0].mu - Vec3::UnitZ()).norm(), 1e-15) << delta;
  }
}

// Protects against: a pyramid texel whose normals cancel exactly (a checkerboard of horizon normals +x / -x): with
// one lobe it must store (alpha, alpha r) = (1, 0), which decodes to the uniform lobe (kappa 0), not NaN; with two
// lobes it must resolve both directions at the cap with half the mass each.
TEST(HardCases, VmfPyramidOnNormalsThatCancel) {
  const NormalMap map = test::filled(4, 4, [](uint32_t x, uint32_t y) { return Vec3((x + y) % 2 ? 1.0 : -1.0, 0, 0); });
  const VmfPyramid one = build_vmf_pyramid(map, nullptr, VmfBakeOptions{1, {}}, Progress::silent());
  for (size_t k = 1; k < one.levels.size(); ++k)
    for (size_t t = 0; t < size_t(one.levels[k].width) * one.levels[k].height; ++t) {
      const float* s = &one.levels[k].lobes[t * 4];
      EXPECT_EQ(s[0], 1.0f);
      EXPECT_EQ(Vec3f(s[1], s[2], s[3]), Vec3f::Zero()) << k;
      const VmfComponent lobe = decode_lobe(s, kVmfKappaMax);
      EXPECT_EQ(lobe.kappa, 0.0);
      EXPECT_TRUE(lobe.mu.allFinite());
    }
  const VmfPyramid two = build_vmf_pyramid(map, nullptr, VmfBakeOptions{2, {}}, Progress::silent());
  for (size_t k = 1; k < two.levels.size(); ++k)
    for (size_t t = 0; t < size_t(two.levels[k].width) * two.levels[k].height; ++t) {
      const VmfComponent a = decode_lobe(&two.levels[k].lobes[t * 8], kVmfKappaMax),
                         b = decode_lobe(&two.levels[k].lobes[t * 8 + 4], kVmfKappaMax);
      EXPECT_NEAR(a.alpha, 0.5, 1e-7);
      EXPECT_NEAR(b.alpha, 0.5, 1e-7);
      EXPECT_EQ(a.kappa, kVmfKappaMax);
      EXPECT_EQ(b.kappa, kVmfKappaMax);
      EXPECT_NEAR(std::abs(a.mu.x()), 1.0, 1e-7);
      EXPECT_NEAR(a.mu.dot(b.mu), -1.0, 1e-7);
    }
}

// Protects against: the band factors losing their relative precision as kappa -> 0 (they are ~kappa^l, far below
// any absolute tolerance): Lambda_l(kappa) = kappa^l / (2l + 1)!! (1 + c kappa^2 + ...), |c| < 1/6, from the series
// I_nu(k) = (k / 2)^nu / Gamma(nu + 1) (1 + (k / 2)^2 / (nu + 1) + ...).
TEST(HardCases, VmfShaderBesselFactorsAtKappaToZero) {
  std::vector<double> lambda(9);
  for (const double kappa : {1e-2, 1e-5, 1e-12, 1e-30}) {
    vmf_band_factors(kappa, lambda);
    double leading = 1.0;  // kappa^l / (2l + 1)!!
    for (int l = 0; l <= 8; ++l) {
      if (l > 0) leading *= kappa / (2.0 * l + 1.0);
      EXPECT_NEAR(lambda[size_t(l)] / leading, 1.0, kappa * kappa / 6 + 1e-13) << "kappa " << kappa << " l " << l;
    }
  }
}

// Protects against: the large-kappa branch drifting from the Bessel ratio (e^kappa overflows past 710, so it cannot
// be evaluated as written): the asymptotic series I_nu(k) ~ e^k / sqrt(2 pi k) (1 - (4 nu^2 - 1) / (8k) + ...) gives
// Lambda_l = 1 - a / (2 kappa) + a (a - 2) / (8 kappa^2) + O(a^3 / kappa^3), a = l (l + 1).
TEST(HardCases, VmfShaderBesselFactorsAtKappaToInfinity) {
  std::vector<double> lambda(33);
  for (const double kappa : {1e4, 1e6, 1e9, 1e15, 1e300}) {
    vmf_band_factors(kappa, lambda);
    for (int l = 0; l <= 32; ++l) {
      const double a = double(l) * (l + 1);
      const double expected = 1.0 - a / (2 * kappa) + a * (a - 2) / (8 * kappa * kappa);
      EXPECT_NEAR(lambda[size_t(l)], expected, a * a * a / (kappa * kappa * kappa) + 2e-12)
          << "kappa " << kappa << " l " << l;
    }
  }
}

// Protects against: the filtered BRDF of a uniform lobe (kappa -> 0) depending on w or on rounding in the band
// factors: a diffuse surface whose normals are uniform over the sphere reflects (1 / 4 pi) int max(w . n, 0) dn =
// 1/4 in every direction, and for small kappa 1/4 + kappa (w . mu) / 6 (the band-1 term, Lambda_1 ~ kappa / 3).
TEST(HardCases, VmfShaderUniformLobeReflectsAQuarter) {
  const std::vector<double> rhat = lambertian_rhat(8);
  for (const double kappa : {0.0, 1e-300, 1e-8}) {
    const VmfLobeShape lobe{1.0, kappa, Vec3(0.6, 0.0, 0.8)};
    for (const Vec3& w : {Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(0.6, 0.0, 0.8), Vec3(0, 0, -1)})
      EXPECT_NEAR(vmf_filtered_brdf(std::span(&lobe, 1), rhat, w), 0.25 + kappa * w.dot(lobe.mu) / 6, 1e-15) << kappa;
  }
}

// Protects against: the sharp end of the shader: a lobe at the kappa cap (and kappa = +inf) must shade as a delta
// at mu, sum_l rhat_l (2l + 1) / (4 pi) P_l(w . mu) (Legendre polynomials by Bonnet's recurrence here), within the
// cap's blur 1 - Lambda_l(1e6) ~ l (l + 1) / 2e6.
TEST(HardCases, VmfShaderLobeAtTheCapShadesAsItsNormal) {
  const std::vector<double> rhat = lambertian_rhat(8);
  const Vec3 mu = Vec3(0.2, -0.3, 0.9).normalized();
  for (const double kappa : {kVmfKappaMax, std::numeric_limits<double>::infinity()}) {
    const VmfLobeShape lobe{0.7, kappa, mu};
    for (const Vec3& w : {mu, Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.3, 0.3, -0.9).normalized()}) {
      const double t = w.dot(mu);
      double delta = 0.0, p0 = 1.0, p1 = t;
      for (int l = 0; l <= 8; ++l) {
        const double p = l == 0 ? 1.0 : l == 1 ? t : ((2.0 * l - 1) * t * p1 - (l - 1.0) * p0) / l;
        if (l >= 2) p0 = p1, p1 = p;
        delta += rhat[size_t(l)] * (2 * l + 1) / (4 * kPi) * p;
      }
      const double blur = std::isinf(kappa) ? 1e-15 : 72.0 / (2 * kappa);
      EXPECT_NEAR(vmf_filtered_brdf(std::span(&lobe, 1), rhat, w), 0.7 * delta, blur) << kappa;
    }
  }
}

// Protects against: a filtered specular lobe that reaches the view horizon shading with its mean's factors (the
// grazing far field): most of the reference's light there comes from the normals behind the view, bent onto it.
// A wide lobe (kappa 4, a third of it behind a view 1 degree above the plane, the light 3 degrees above on the far
// side) within 8% of its mean by rejection sampling; a lobe whose mean lies exactly on the view horizon (mu . v = 0)
// and a light exactly on the lobe's horizon (mu . l = 0) finite, non-negative and within 8%; kappa 1e-300 and 1e6
// at the view horizon finite and within 8% / equal to the bent normal's shading.
TEST(HardCases, VmfShaderLobeReachingTheViewHorizon) {
  const Brdf brdf{Vec3::Zero(), Vec3(0.5, 0.5, 0.5), {Distribution::ggx, 0.15}};
  const auto at = [](double elevation_degrees, double azimuth_degrees) {
    const double e = elevation_degrees * kPi / 180, a = azimuth_degrees * kPi / 180;
    return Vec3(std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e));
  };
  const auto specular = [&](const Vec3& mu, double kappa, const Vec3& l, const Vec3& v) {
    const SpecularLobe lobe{1.0, mu, kappa, clamp_filtered_alpha(0.15, vmf_filtered_beckmann_alpha(0.15, kappa))};
    return lobes_specular(brdf, {&lobe, 1}, l, v)[0];
  };
  const Vec3 v = at(1.0, 0.0), l = at(3.0, 180.0);
  struct Case {
    Vec3 mu;
    double kappa;
    Vec3 l;
  };
  const Vec3 on_view_horizon = Vec3(0.0, 0.0, 1.0).cross(v).cross(v).normalized() * -1.0;
  for (const Case& c : {Case{Vec3::UnitZ(), 4.0, l}, Case{on_view_horizon, 10.0, l},
                        Case{Vec3::UnitZ(), 20.0, at(0.0, 180.0)}, Case{Vec3::UnitZ(), 1e-300, l}}) {
    const double s = specular(c.mu, c.kappa, c.l, v);
    ASSERT_TRUE(std::isfinite(s)) << c.kappa;
    EXPECT_GE(s, 0.0) << c.kappa;
    const double reference = test::lobe_mean_by_rejection(brdf, c.mu, c.kappa, c.l, v, 40000);
    EXPECT_NEAR(s, reference, 0.08 * reference + 1e-4) << "mu " << c.mu.transpose() << ", kappa " << c.kappa;
  }
  const double sharp = specular(Vec3::UnitZ(), 1e6, l, v);
  EXPECT_TRUE(std::isfinite(sharp));
  EXPECT_NEAR(sharp, test::reference_specular(brdf, Vec3::UnitZ(), l, v),
              0.08 * test::reference_specular(brdf, Vec3::UnitZ(), l, v));
}

}  // namespace
}  // namespace mbk
