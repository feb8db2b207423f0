// The specular reflection of a mixture of vMF lobes of shading normals (see lobe_specular.h).
#include "libbake/eval/lobe_specular.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

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

// The Fibonacci lattice u_i = ((i + 1/2) / N, frac((i + 1/2) F' / N)) with N = kLobeSpecularPoints = F_k and
// F' = F_{k-1} (the two-dimensional rank-1 rule with the most even spacing for its size), with what every point set
// needs of u2: cos and sin of 2 pi u2 and tan(pi (u2 - 1/2)).
struct LatticePoint {
  double u1, cos_phi, sin_phi, tan_centred;
};
const std::array<LatticePoint, kLobeSpecularPoints>& lattice() {
  static const std::array<LatticePoint, kLobeSpecularPoints> points = [] {
    std::array<LatticePoint, kLobeSpecularPoints> a{};
    for (int i = 0; i < kLobeSpecularPoints; ++i) {
      const double u2 = std::fmod((i + 0.5) * kLobeSpecularGenerator / kLobeSpecularPoints, 1.0);
      a[size_t(i)] = {(i + 0.5) / kLobeSpecularPoints, std::cos(kTwoPi * u2), std::sin(kTwoPi * u2),
                      std::tan(std::numbers::pi * (u2 - 0.5))};
    }
    return a;
  }();
  return points;
}

// tan^2 of a microfacet normal's angle from the mean at u in (0, 1) for D(m) (m . n) as a density.
double microfacet_inverse_cdf_tan2(const MicrofacetLobe& lobe, double u) {
  const double a2 = lobe.alpha * lobe.alpha;
  return lobe.distribution == Distribution::beckmann ? -a2 * std::log1p(-u) : a2 * u / (1.0 - u);
}

Vec3 direction(const Vec3& z, const Vec3& x, const Vec3& y, double cos_theta, double cos_phi, double sin_phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return (cos_theta * z + s * cos_phi * x + s * sin_phi * y).normalized();
}

// Points behind the view horizon, for the normals the reference bends onto it: in cylindrical coordinates about v
// (t = n . v, psi the azimuth about v; the sphere's area element is dt dpsi), psi from a wrapped Cauchy about h's
// azimuth (the bent normal's D falls off like a Cauchy density around there) and t in [-1, kMinCosView) from a
// density proportional to exp(a t) with a = kappa (mu . v) (the lobe's fall-off along t, its azimuthal term left
// out: the MIS weights account for it). Angles enter only through cosines and sines, without trigonometry.
class BehindHorizon {
 public:
  BehindHorizon(const Vec3& v, const Vec3& h, double alpha, double lobe_slope) : v_(v), a_(lobe_slope) {
    complete_frame(v, e1_, e2_);
    const double h1 = h.dot(e1_), h2 = h.dot(e2_), across = std::hypot(h1, h2);
    cos_h_ = across > 0.0 ? h1 / across : 1.0;
    sin_h_ = across > 0.0 ? h2 / across : 0.0;
    const double delta = std::asin(std::clamp(h.dot(v), -1.0, 1.0));  // h's angle from the horizon circle
    rho_ = std::exp(-std::sqrt(alpha * alpha + delta * delta));
    tan_scale_ = (1.0 - rho_) / (1.0 + rho_);
    rate_ = std::abs(a_);
    expm1_rate_ = std::expm1(-rate_ * kLength);
  }
  Vec3 point(const LatticePoint& u) const {
    // psi = psi_h + 2 atan(x): cos and sin of 2 atan(x) are (1 - x^2, 2 x) / (1 + x^2).
    const double x = tan_scale_ * u.tan_centred, d = 1.0 + x * x;
    const double cos_d = (1.0 - x * x) / d, sin_d = 2.0 * x / d;
    const double cos_psi = cos_h_ * cos_d - sin_h_ * sin_d, sin_psi = sin_h_ * cos_d + cos_h_ * sin_d;
    // s >= 0 from the end of the interval the density leans towards, exponential of rate |a| (exponents <= 0).
    const double s_end = rate_ < 1e-9 ? u.u1 * kLength : -std::log1p(u.u1 * expm1_rate_) / rate_;
    const double t = std::clamp(a_ > 0.0 ? kMinCosView - s_end : -1.0 + s_end, -1.0, kMinCosView);
    const double s = std::sqrt(std::max(0.0, 1.0 - t * t));
    return (t * v_ + s * (cos_psi * e1_ + sin_psi * e2_)).normalized();
  }
  // The density of point() at n (0 in front of the horizon).
  double density(const Vec3& n) const {
    const double t = n.dot(v_);
    if (!(t < kMinCosView)) return 0.0;
    const double n1 = n.dot(e1_), n2 = n.dot(e2_), across = std::sqrt(n1 * n1 + n2 * n2);
    const double cos_off = across > 0.0 ? (n1 * cos_h_ + n2 * sin_h_) / across : 1.0;  // cos(psi - psi_h)
    const double wrapped = (1.0 - rho_ * rho_) / (kTwoPi * (1.0 + rho_ * rho_ - 2.0 * rho_ * cos_off));
    const double s_end = a_ > 0.0 ? kMinCosView - t : t + 1.0;
    const double along = rate_ < 1e-9 ? 1.0 / kLength : rate_ * std::exp(-rate_ * s_end) / -expm1_rate_;
    return wrapped * along;
  }

 private:
  static constexpr double kLength = 1.0 + kMinCosView;  // of t's interval [-1, kMinCosView)
  Vec3 v_, e1_, e2_;
  double a_, cos_h_ = 1.0, sin_h_ = 0.0, rho_ = 0.0, tan_scale_ = 0.0;
  double rate_ = 0.0, expm1_rate_ = 0.0;  // |a| and expm1(-|a| kLength)
};

// Whether [Han07]'s widened lobe at the (bent) mean stands for the lobe: its spread sqrt(2 / kappa) is under a
// third of the cosines to the view's and the light's horizons.
bool narrow(const SpecularLobe& lobe, const Vec3& bent_mu, const Vec3& l, const Vec3& v) {
  const double spread = lobe.kappa > 0.0 ? std::sqrt(2.0 / lobe.kappa) : INFINITY;
  return 3.0 * spread <= std::min(bent_mu.dot(v), bent_mu.dot(l));
}

}  // namespace

Vec3 lobes_specular_integrated(const Brdf& brdf, std::span<const SpecularLobe> lobes, const Vec3& l, const Vec3& v) {
  const Vec3 sum = l + v;
  if (!(sum.norm() > 0.0)) return Vec3::Zero();
  const Vec3 h = sum.normalized();
  // Phi(n) / F, the reference's specular times cosine for one texel normal n (bent as the reference bends it)
  // without the Fresnel factor, which depends on v . h alone (evaluate_specular, microfacet_brdf.h).
  const auto phi = [&](const Vec3& n) {
    const Vec3 bent = facing_viewer(n, v);
    const double cos_l = bent.dot(l), cos_v = bent.dot(v);
    if (!(cos_l > 0.0 && cos_v > 0.0)) return 0.0;
    return microfacet_d(brdf.lobe, bent.dot(h)) * smith_g2(brdf.lobe, cos_l, cos_v) / (4.0 * cos_v);
  };
  // Per lobe: its frame and log normalisation.
  struct Prepared {
    Vec3 x, y;
    double log_norm;
  };
  std::vector<Prepared> prepared(lobes.size());
  double lobe_slope = 0.0, total = 0.0;
  for (size_t j = 0; j < lobes.size(); ++j) {
    complete_frame(lobes[j].mu, prepared[j].x, prepared[j].y);
    prepared[j].log_norm = vmf_log_density(lobes[j].kappa, 1.0);
    lobe_slope += lobes[j].weight * lobes[j].kappa * lobes[j].mu.dot(v);
    total += lobes[j].weight;
  }
  // The integrand's density, the mixture sum_j w_j p_j, and the sampling density of all lobe points together,
  // K sum_j p_j (each lobe gets K points whatever its weight).
  constexpr double k = kLobeSpecularPoints;
  const auto densities = [&](const Vec3& n, double& mixture, double& sampled) {
    mixture = sampled = 0.0;
    for (size_t j = 0; j < lobes.size(); ++j) {
      const double p = std::exp(prepared[j].log_norm + lobes[j].kappa * (lobes[j].mu.dot(n) - 1.0));
      mixture += lobes[j].weight * p;
      sampled += k * p;
    }
  };
  // D's points count in front of the view horizon, the horizon points behind it.
  const BehindHorizon behind(v, h, brdf.lobe.alpha, total > 0.0 ? lobe_slope / total : 0.0);
  const auto other_densities = [&](const Vec3& n) {
    if (n.dot(v) < kMinCosView) return k * behind.density(n);
    const double c = h.dot(n);
    return c > 0.0 ? k * microfacet_d(brdf.lobe, c) * c : 0.0;
  };
  const auto add = [&](const Vec3& n, double& s) {
    double mixture, sampled;
    densities(n, mixture, sampled);
    if (mixture > 0.0) s += phi(n) * (mixture / (sampled + other_densities(n)));
  };
  double s = 0.0;
  for (size_t j = 0; j < lobes.size(); ++j)
    for (const LatticePoint& u : lattice()) {
      // Behind the view horizon only the lobes' points reach a normal; in front, D's points share it.
      const double w = vmf_cos_from_uniform(lobes[j].kappa, 1.0 - u.u1);
      add(direction(lobes[j].mu, prepared[j].x, prepared[j].y, w, u.cos_phi, u.sin_phi), s);
    }
  Vec3 x, y;
  complete_frame(h, x, y);
  for (const LatticePoint& u : lattice()) {
    const double tan2 = microfacet_inverse_cdf_tan2(brdf.lobe, u.u1);
    const Vec3 m = direction(h, x, y, 1.0 / std::sqrt(1.0 + tan2), u.cos_phi, u.sin_phi);
    if (m.dot(v) >= kMinCosView) add(m, s);
    add(behind.point(u), s);
  }
  return schlick_fresnel(brdf.f0, v.dot(h)) * s;
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

bool lobe_specular_is_product(const SpecularLobe& lobe, const Vec3& l, const Vec3& v) {
  return !(lobe.kappa < INFINITY) || narrow(lobe, facing_viewer(lobe.mu, v), l, v);
}

Vec3 lobe_corrected_specular(const Vec3& product, const Vec3& lobe_product, const Vec3& lobe_integrated) {
  Vec3 out;
  for (int c = 0; c < 3; ++c) {
    const double p = product[c], q = lobe_product[c], integrated = lobe_integrated[c];
    out[c] = p < q ? p * integrated / q : integrated + (p - q);
  }
  return out;
}

}  // namespace mbk
