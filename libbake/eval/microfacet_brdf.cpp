// Lambert + microfacet specular (Beckmann or GGX, height-correlated Smith, Schlick); see microfacet_brdf.h.
#include "libbake/eval/microfacet_brdf.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

// tan^2(th) from cos(th) > 0.
double tan2_of(double c) { return std::max(0.0, 1.0 - c * c) / (c * c); }

}  // namespace

double microfacet_d(const MicrofacetLobe& lobe, double c) {
  if (!(c > 0.0)) return 0.0;
  const double a2 = lobe.alpha * lobe.alpha;
  if (lobe.distribution == Distribution::ggx) {
    const double k = c * c * (a2 - 1.0) + 1.0;
    return a2 / (kPi * k * k);
  }
  const double e = tan2_of(c) / a2;
  // exp(-700) is below the smallest normal double; beyond it the quotient below would be 0 / 0 as
  // cos^4 underflows first (covered by MicrofacetBrdf.FiniteAtTheHorizonAndZeroBelowIt).
  if (e > 700.0) return 0.0;
  return std::exp(-e) / (kPi * a2 * c * c * c * c);
}

double smith_lambda(const MicrofacetLobe& lobe, double c) {
  if (c >= 1.0) return 0.0;
  if (!(c > 0.0)) return std::numeric_limits<double>::infinity();  // at or below the horizon: fully masked
  const double a2t2 = lobe.alpha * lobe.alpha * tan2_of(c);
  if (lobe.distribution == Distribution::ggx) return 0.5 * (-1.0 + std::sqrt(1.0 + a2t2));
  const double a = 1.0 / std::sqrt(a2t2);
  // (erf(a) - 1) / 2 written with erfc, which keeps its digits when erf(a) is close to 1.
  return -0.5 * std::erfc(a) + std::exp(-a * a) / (2.0 * a * std::sqrt(kPi));
}

double smith_g1(const MicrofacetLobe& lobe, double c) { return 1.0 / (1.0 + smith_lambda(lobe, c)); }

double smith_g2(const MicrofacetLobe& lobe, double cos_l, double cos_v) {
  return 1.0 / (1.0 + smith_lambda(lobe, cos_l) + smith_lambda(lobe, cos_v));
}

Vec3 schlick_fresnel(const Vec3& f0, double cos_d) {
  const double m = 1.0 - std::clamp(cos_d, 0.0, 1.0);
  const double m5 = m * m * m * m * m;
  return f0 + (Vec3::Ones() - f0) * m5;
}

Vec3 evaluate_specular(const Brdf& b, const Vec3& n, const Vec3& l, const Vec3& v) {
  return evaluate_specular(b, n, l, v, [&](const Vec3& h) { return microfacet_d(b.lobe, n.dot(h)); });
}

Vec3 evaluate_specular(const Brdf& b, const Vec3& n, const Vec3& l, const Vec3& v,
                       const std::function<double(const Vec3& h)>& distribution) {
  const double cl = n.dot(l), cv = n.dot(v);
  if (!(cl > 0.0 && cv > 0.0)) return Vec3::Zero();
  const Vec3 sum = l + v;
  const double len = sum.norm();
  if (!(len > 0.0)) return Vec3::Zero();  // l = -v cannot happen with both above the horizon; kept for NaN inputs
  const Vec3 h = sum / len;
  const double d = distribution(h);
  const double g = smith_g2(b.lobe, cl, cv);
  return schlick_fresnel(b.f0, v.dot(h)) * (d * g / (4.0 * cl * cv));
}

Vec3 evaluate_brdf(const Brdf& b, const Vec3& n, const Vec3& l, const Vec3& v) {
  if (!(n.dot(l) > 0.0 && n.dot(v) > 0.0)) return Vec3::Zero();
  return b.albedo / kPi + evaluate_specular(b, n, l, v);
}

}  // namespace mbk
