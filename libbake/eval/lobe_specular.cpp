// The specular reflection of a mixture of vMF lobes of shading normals (see lobe_specular.h).
#include "libbake/eval/lobe_specular.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "libbake/core/vmf_lobe.h"
#include "libbake/eval/scene_lighting.h"

namespace mbk {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Two unit vectors completing z to an orthonormal frame.
void complete_frame(const Vec3& z, Vec3& x, Vec3& y) {
  const Vec3 t = std::abs(z.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  x = (t - z * z.dot(t)).normalized();
  y = z.cross(x);
}

// The i-th of the kLobeSpecularPoints points of the Fibonacci lattice (i + 1/2) / N, frac((i + 1/2) F' / N) with
// N = F_k and F' = F_{k-1}, the two-dimensional rank-1 rule with the most even spacing for its size.
void lattice_point(int i, double& u1, double& u2) {
  u1 = (i + 0.5) / kLobeSpecularPoints;
  u2 = std::fmod((i + 0.5) * kLobeSpecularGenerator / kLobeSpecularPoints, 1.0);
}

// cos(angle from mu) of the vMF's inverse CDF at u in (0, 1): w = 1 + log(1 + (1 - u) expm1(-2 kappa)) / kappa
// (no cancellation for small kappa; kappa -> 0 gives the uniform 2 u - 1).
double vmf_inverse_cdf(double kappa, double u) {
  if (kappa < 1e-9) return 2.0 * u - 1.0;
  return std::clamp(1.0 + std::log1p((1.0 - u) * std::expm1(-2.0 * kappa)) / kappa, -1.0, 1.0);
}

// tan^2 of a microfacet normal's angle from the mean at u in (0, 1) for D(m) (m . n) as a density.
double microfacet_inverse_cdf_tan2(const MicrofacetLobe& lobe, double u) {
  const double a2 = lobe.alpha * lobe.alpha;
  return lobe.distribution == Distribution::beckmann ? -a2 * std::log1p(-u) : a2 * u / (1.0 - u);
}

Vec3 direction(const Vec3& z, const Vec3& x, const Vec3& y, double cos_theta, double phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return (cos_theta * z + s * std::cos(phi) * x + s * std::sin(phi) * y).normalized();
}

// Points behind the view horizon, for the normals the reference bends onto it: in cylindrical coordinates about v
// (t = n . v, psi the azimuth about v; the sphere's area element is dt dpsi), psi from a wrapped Cauchy about h's
// azimuth (the bent normal's D falls off like a Cauchy density around there) and t in [-1, kMinCosView) from a
// density proportional to exp(a t) with a = kappa (mu . v) (the lobe's fall-off along t, its azimuthal term left
// out: the MIS weights account for it).
class BehindHorizon {
 public:
  BehindHorizon(const Vec3& v, const Vec3& h, double alpha, double lobe_slope) : v_(v), a_(lobe_slope) {
    complete_frame(v, e1_, e2_);
    psi_h_ = std::atan2(h.dot(e2_), h.dot(e1_));
    const double delta = std::asin(std::clamp(h.dot(v), -1.0, 1.0));  // h's angle from the horizon circle
    rho_ = std::exp(-std::sqrt(alpha * alpha + delta * delta));
  }
  Vec3 point(double u1, double u2) const {
    const double psi = psi_h_ + 2.0 * std::atan((1.0 - rho_) / (1.0 + rho_) * std::tan(std::numbers::pi * (u2 - 0.5)));
    // s >= 0 from the end of the interval the density leans towards, exponential of rate |a| (exponents <= 0).
    const double rate = std::abs(a_);
    const double s_end = rate < 1e-9 ? u1 * kLength : -std::log1p(u1 * std::expm1(-rate * kLength)) / rate;
    const double t = std::clamp(a_ > 0.0 ? kMinCosView - s_end : -1.0 + s_end, -1.0, kMinCosView);
    const double s = std::sqrt(std::max(0.0, 1.0 - t * t));
    return (t * v_ + s * (std::cos(psi) * e1_ + std::sin(psi) * e2_)).normalized();
  }
  // The density of point() at n (0 in front of the horizon).
  double density(const Vec3& n) const {
    const double t = n.dot(v_);
    if (!(t < kMinCosView)) return 0.0;
    const double psi = std::atan2(n.dot(e2_), n.dot(e1_));
    const double wrapped = (1.0 - rho_ * rho_) / (kTwoPi * (1.0 + rho_ * rho_ - 2.0 * rho_ * std::cos(psi - psi_h_)));
    const double rate = std::abs(a_), s_end = a_ > 0.0 ? kMinCosView - t : t + 1.0;
    const double along = rate < 1e-9 ? 1.0 / kLength : rate * std::exp(-rate * s_end) / -std::expm1(-rate * kLength);
    return wrapped * along;
  }

 private:
  static constexpr double kLength = 1.0 + kMinCosView;  // of t's interval [-1, kMinCosView)
  Vec3 v_, e1_, e2_;
  double a_, psi_h_ = 0.0, rho_ = 0.0;
};

// Whether [Han07]'s widened lobe at the (bent) mean stands for the lobe: its spread sqrt(2 / kappa) is under a
// third of the cosines to the view's and the light's horizons.
bool narrow(const SpecularLobe& lobe, const Vec3& bent_mu, const Vec3& l, const Vec3& v) {
  const double spread = lobe.kappa > 0.0 ? std::sqrt(2.0 / lobe.kappa) : INFINITY;
  return 3.0 * spread <= std::min(bent_mu.dot(v), bent_mu.dot(l));
}

}  // namespace

Vec3 lobes_specular_integrated(const Brdf& brdf, std::span<const SpecularLobe> lobes, const Vec3& l, const Vec3& v) {
  // Phi(n), the reference's specular times cosine for one texel normal n (bent as the reference bends it).
  const auto phi = [&](const Vec3& n) -> Vec3 {
    const Vec3 bent = facing_viewer(n, v);
    const double cos_l = bent.dot(l);
    return cos_l > 0.0 ? Vec3(evaluate_specular(brdf, bent, l, v) * cos_l) : Vec3(Vec3::Zero());
  };
  const Vec3 sum = l + v;
  if (!(sum.norm() > 0.0)) return Vec3::Zero();
  const Vec3 h = sum.normalized();
  // The integrand's density, the mixture sum_j w_j p_j, and the sampling density of all lobe points together,
  // K sum_j p_j (each lobe gets K points whatever its weight).
  constexpr double k = kLobeSpecularPoints;
  const auto densities = [&](const Vec3& n, double& mixture, double& sampled) {
    mixture = sampled = 0.0;
    for (const SpecularLobe& lobe : lobes) {
      const double p = std::exp(vmf_log_density(lobe.kappa, lobe.mu.dot(n)));
      mixture += lobe.weight * p;
      sampled += k * p;
    }
  };
  // D's points count in front of the view horizon, the horizon points behind it.
  double lobe_slope = 0.0, total = 0.0;
  for (const SpecularLobe& lobe : lobes) {
    lobe_slope += lobe.weight * lobe.kappa * lobe.mu.dot(v);
    total += lobe.weight;
  }
  const BehindHorizon behind(v, h, brdf.lobe.alpha, total > 0.0 ? lobe_slope / total : 0.0);
  const auto other_densities = [&](const Vec3& n) {
    if (n.dot(v) < kMinCosView) return k * behind.density(n);
    const double c = h.dot(n);
    return c > 0.0 ? k * microfacet_d(brdf.lobe, c) * c : 0.0;
  };
  Vec3 s = Vec3::Zero();
  for (const SpecularLobe& lobe : lobes) {
    Vec3 x, y;
    complete_frame(lobe.mu, x, y);
    for (int i = 0; i < kLobeSpecularPoints; ++i) {
      double u1, u2, mixture, sampled;
      lattice_point(i, u1, u2);
      // Behind the view horizon only the lobes' points reach a normal; in front, D's points share it.
      const Vec3 n = direction(lobe.mu, x, y, vmf_inverse_cdf(lobe.kappa, u1), kTwoPi * u2);
      densities(n, mixture, sampled);
      if (mixture > 0.0) s += phi(n) * (mixture / (sampled + other_densities(n)));
    }
  }
  Vec3 x, y;
  complete_frame(h, x, y);
  for (int i = 0; i < kLobeSpecularPoints; ++i) {
    double u1, u2, mixture, sampled;
    lattice_point(i, u1, u2);
    const double tan2 = microfacet_inverse_cdf_tan2(brdf.lobe, u1);
    const Vec3 m = direction(h, x, y, 1.0 / std::sqrt(1.0 + tan2), kTwoPi * u2);
    if (m.dot(v) >= kMinCosView) {
      densities(m, mixture, sampled);
      if (mixture > 0.0) s += phi(m) * (mixture / (sampled + other_densities(m)));
    }
    const Vec3 b = behind.point(u1, u2);
    densities(b, mixture, sampled);
    if (mixture > 0.0) s += phi(b) * (mixture / (sampled + other_densities(b)));
  }
  return s;
}

Vec3 lobes_specular(const Brdf& brdf, std::span<const SpecularLobe> lobes, const Vec3& l, const Vec3& v) {
  Vec3 out = Vec3::Zero();
  std::vector<SpecularLobe> wide;
  for (const SpecularLobe& lobe : lobes) {
    if (!(lobe.weight > 0.0)) continue;
    const Vec3 n = facing_viewer(lobe.mu, v);
    if (!(lobe.kappa < INFINITY)) {  // one normal: exactly the reference's
      const double cos_l = n.dot(l);
      if (cos_l > 0.0) out += lobe.weight * evaluate_specular(brdf, n, l, v) * cos_l;
    } else if (narrow(lobe, n, l, v)) {
      Brdf widened = brdf;
      widened.lobe.alpha = lobe.widened_alpha;
      out += lobe.weight * evaluate_specular(widened, n, l, v) * std::max(0.0, n.dot(l));
    } else {
      wide.push_back(lobe);
    }
  }
  if (!wide.empty()) out += lobes_specular_integrated(brdf, wide, l, v);
  return out;
}

}  // namespace mbk
