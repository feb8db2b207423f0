// The BRDF: D integrates to 1 as a projected area (numerical integration), Smith G1 satisfies the weak
// white furnace test of the visible normals (Heitz 2014, Eq. 11), f is reciprocal, Lambert reflects all
// and the microfacet lobe never more than all of the light, and nothing overflows at the horizon.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "libbake/eval/microfacet_brdf.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<MicrofacetLobe> lobes() {
  std::vector<MicrofacetLobe> out;
  for (Distribution d : {Distribution::beckmann, Distribution::ggx})
    for (double a : {0.05, 0.2, 0.5, 1.0}) out.push_back({d, a});
  return out;
}

Vec3 spherical(double theta, double phi) {
  return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

TEST(MicrofacetBrdf, NdfIntegratesToOneAsProjectedArea) {
  for (const auto& lobe : lobes()) {
    // 2 pi * integral over theta of D(cos) cos sin; midpoint rule, fine enough for alpha = 0.05.
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) * (kPi / 2) / n;
      sum += microfacet_d(lobe, std::cos(t)) * std::cos(t) * std::sin(t);
    }
    EXPECT_NEAR(2 * kPi * sum * (kPi / 2) / n, 1.0, 2e-4)
        << distribution_name(lobe.distribution) << " alpha " << lobe.alpha;
  }
}

TEST(MicrofacetBrdf, SmithG1PassesTheWeakWhiteFurnaceTest) {
  // integral over m of G1(v) D(m) max(0, v.m) = cos(theta_v): G1 is the right normalisation of visible normals.
  for (const auto& lobe : lobes()) {
    if (lobe.alpha < 0.1) continue;  // too narrow for this grid; covered by the 1-D test above
    for (double theta_v : {0.0, 0.5, 1.0, 1.4}) {
      const Vec3 v = spherical(theta_v, 0.3);
      const int nt = 1000, np = 400;
      double sum = 0;
      for (int i = 0; i < nt; ++i) {
        const double t = (i + 0.5) * (kPi / 2) / nt;
        for (int j = 0; j < np; ++j) {
          const Vec3 m = spherical(t, (j + 0.5) * 2 * kPi / np);
          sum += microfacet_d(lobe, m.z()) * std::max(0.0, v.dot(m)) * std::sin(t);
        }
      }
      const double integral = sum * (kPi / 2 / nt) * (2 * kPi / np) * smith_g1(lobe, v.z());
      EXPECT_NEAR(integral, std::cos(theta_v), 2e-3)
          << distribution_name(lobe.distribution) << " alpha " << lobe.alpha << " theta_v " << theta_v;
    }
  }
}

TEST(MicrofacetBrdf, IsReciprocal) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> theta(0.0, 1.5), phi(0.0, 2 * kPi);
  for (const auto& lobe : lobes()) {
    const Brdf b{Vec3(0.2, 0.5, 0.7), Vec3(0.04, 0.5, 0.9), lobe};
    for (int k = 0; k < 200; ++k) {
      const Vec3 l = spherical(theta(rng), phi(rng)), v = spherical(theta(rng), phi(rng));
      const Vec3 f1 = evaluate_brdf(b, Vec3::UnitZ(), l, v), f2 = evaluate_brdf(b, Vec3::UnitZ(), v, l);
      EXPECT_LT((f1 - f2).norm(), 1e-12 * (1 + f1.norm()));
    }
  }
}

// Directional albedo: integral over l of f(l, v) cos(theta_l).
Vec3 albedo(const Brdf& b, const Vec3& v) {
  const int nt = 1500, np = 300;
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < nt; ++i) {
    const double t = (i + 0.5) * (kPi / 2) / nt;
    for (int j = 0; j < np; ++j) {
      const Vec3 l = spherical(t, (j + 0.5) * 2 * kPi / np);
      sum += evaluate_brdf(b, Vec3::UnitZ(), l, v) * (l.z() * std::sin(t));
    }
  }
  return sum * (kPi / 2 / nt) * (2 * kPi / np);
}

TEST(MicrofacetBrdf, LambertReflectsEverythingAndSpecularNeverMore) {
  // Schlick's term is not zero at grazing angles even for F0 = 0, so the diffuse part is taken alone.
  const Brdf lambert{Vec3::Ones(), Vec3::Zero(), {Distribution::ggx, 0.5}};
  const Brdf no_diffuse{Vec3::Zero(), Vec3::Zero(), {Distribution::ggx, 0.5}};
  const Vec3 v = spherical(0.7, 0.0);
  EXPECT_NEAR(albedo(lambert, v).x() - albedo(no_diffuse, v).x(), 1.0, 1e-5);
  for (const auto& lobe : lobes()) {
    if (lobe.alpha < 0.1) continue;
    const Brdf mirror_like{Vec3::Zero(), Vec3::Ones(), lobe};  // F = 1: only shadowing-masking loses energy
    for (double theta_v : {0.0, 0.8, 1.3}) {
      const double a = albedo(mirror_like, spherical(theta_v, 0.0)).x();
      EXPECT_LE(a, 1.0 + 2e-3) << distribution_name(lobe.distribution) << " alpha " << lobe.alpha << " theta_v "
                               << theta_v;
      // Single scattering loses what multiple scattering would return: little for smooth lobes, up to ~70%
      // for alpha = 1 (see the closed form below).
      EXPECT_GT(a, lobe.alpha <= 0.2 && theta_v == 0.0 ? 0.9 : 0.25)
          << distribution_name(lobe.distribution) << " alpha " << lobe.alpha;
    }
  }
}

TEST(MicrofacetBrdf, GgxAlphaOneAlbedoAtNormalIncidenceIsOneMinusLn2) {
  // alpha = 1 makes D = 1/pi; with v = n, h at th_h reflects l to 2 th_h, G2 = 2 cos(th_l) / (1 + cos(th_l)),
  // and the albedo integral becomes integral over c = cos(2 th_h) in [0, 1] of c / (1 + c) = 1 - ln 2.
  const Brdf b{Vec3::Zero(), Vec3::Ones(), {Distribution::ggx, 1.0}};
  EXPECT_NEAR(albedo(b, Vec3::UnitZ()).x(), 1.0 - std::log(2.0), 1e-4);
}

TEST(MicrofacetBrdf, FiniteAtTheHorizonAndZeroBelowIt) {
  for (const auto& lobe : lobes()) {
    for (double c : {0.0, 1e-300, 1e-160, 1e-8, 1.0}) {
      EXPECT_TRUE(std::isfinite(microfacet_d(lobe, c))) << c;
      EXPECT_TRUE(std::isfinite(smith_g1(lobe, c))) << c;
      EXPECT_GE(smith_g1(lobe, c), 0.0);
    }
    EXPECT_EQ(microfacet_d(lobe, -0.5), 0.0);
    EXPECT_EQ(smith_g1(lobe, 0.0), 0.0);
    EXPECT_EQ(smith_g1(lobe, 1.0), 1.0);
    const Brdf b{Vec3::Ones(), Vec3::Ones(), lobe};
    EXPECT_EQ(evaluate_brdf(b, Vec3::UnitZ(), spherical(1.0, 0), spherical(1.8, 0)), Vec3::Zero());
  }
}

TEST(MicrofacetBrdf, SchlickFresnelEndpoints) {
  const Vec3 f0(0.04, 0.5, 1.0);
  EXPECT_LT((schlick_fresnel(f0, 1.0) - f0).norm(), 1e-15);
  EXPECT_LT((schlick_fresnel(f0, 0.0) - Vec3::Ones()).norm(), 1e-15);
}

}  // namespace
}  // namespace mbk

namespace mbk {
namespace {

// The overload with a given distribution (used by glints) is the same formula: with the lobe's own D it gives
// the same value, and it is linear in D.
TEST(MicrofacetBrdf, SpecularWithAGivenDistributionIsTheSameFormula) {
  const Brdf b{Vec3(0.5, 0.5, 0.5), Vec3(0.04, 0.5, 0.9), {Distribution::beckmann, 0.3}};
  const Vec3 n(0, 0, 1), l = Vec3(0.3, 0.1, 0.9).normalized(), v = Vec3(-0.2, 0.25, 0.8).normalized();
  const Vec3 lobe = evaluate_specular(b, n, l, v);
  const Vec3 given = evaluate_specular(b, n, l, v, [&](const Vec3& h) { return microfacet_d(b.lobe, n.dot(h)); });
  EXPECT_EQ(lobe, given);
  const Vec3 twice = evaluate_specular(b, n, l, v, [&](const Vec3& h) { return 2.0 * microfacet_d(b.lobe, n.dot(h)); });
  EXPECT_NEAR((twice - 2.0 * lobe).norm(), 0.0, 1e-12 * lobe.norm());
  EXPECT_EQ(evaluate_specular(b, n, Vec3(0, 0, -1), v, [](const Vec3&) { return 1.0; }), Vec3::Zero());
}

}  // namespace
}  // namespace mbk
