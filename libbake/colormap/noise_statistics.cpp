// Footprint statistics of fractal gradient noise (see noise_statistics.h for the derivation).
#include "libbake/colormap/noise_statistics.h"

#include <algorithm>
#include <cmath>

#include "libbake/core/gauss_legendre.h"
#include "libbake/core/hash.h"
#include "libbake/gen/periodic_noise.h"

namespace mbk {
namespace {

constexpr double kGradientSecondMoment = 0.75;  // E[g_x^2] = E[g_y^2] over the 8 gradients; E[g_x g_y] = 0
constexpr int kTableStepsPerOctave = 8;
constexpr int kTableMinLog2 = -10, kTableMaxLog2 = 8;  // w from 2^-10 to 256 cells

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
// The corner weight K(t) = 1 - fade(|t|) on |t| < 1, 0 beyond.
double kernel(double t) { return std::abs(t) < 1.0 ? 1.0 - fade(std::abs(t)) : 0.0; }
// int_0^t K (odd in t) and int_0^t s K(s) ds (even in t), constant beyond |t| = 1.
double kernel_integral(double t) {
  const double u = std::min(std::abs(t), 1.0);
  const double q = u - (u * u * u * u * (u * (u - 3.0) + 2.5));
  return t < 0 ? -q : q;
}
double ramp_integral(double t) {
  const double u = std::min(std::abs(t), 1.0);
  return 0.5 * u * u - u * u * u * u * u * (u * (u * (6.0 / 7.0) - 2.5) + 2.0);
}

const std::vector<QuadratureNode>& rule8() {
  static const std::vector<QuadratureNode> r = gauss_legendre_nodes(8);
  return r;
}

// int_{-1}^{1} f over the two polynomial pieces of K.
template <typename F>
double integrate_kernel_support(F f) {
  double s = 0.0;
  for (double lo : {-1.0, 0.0})
    for (const QuadratureNode& q : rule8()) s += 0.5 * q.w * f(lo + 0.5 + 0.5 * q.x);
  return s;
}

}  // namespace

NoiseFootprintTable::Axis NoiseFootprintTable::axis_exact(double w) {
  if (!(w > 0.0)) {
    const double a0 = integrate_kernel_support([](double t) { return kernel(t) * kernel(t) * t * t; });
    const double b0 = integrate_kernel_support([](double t) { return kernel(t) * kernel(t); });
    return {a0, b0, a0, b0};
  }
  // The integrand in x0 is a polynomial between the points where x0, x0 + w / 2 or x0 + w crosses an integer.
  std::vector<double> cuts = {0.0, 1.0};
  for (double shift : {w, 0.5 * w}) {
    const double p = std::ceil(shift) - shift;  // x0 + shift is an integer at x0 = p (mod 1)
    if (p > 0.0 && p < 1.0) cuts.push_back(p);
  }
  std::sort(cuts.begin(), cuts.end());
  Axis sum{0, 0, 0, 0};
  for (size_t piece = 0; piece + 1 < cuts.size(); ++piece) {
    const double lo = cuts[piece], hi = cuts[piece + 1];
    if (!(hi > lo)) continue;
    for (const QuadratureNode& q : rule8()) {
      const double x0 = lo + (hi - lo) * 0.5 * (1.0 + q.x), weight = 0.5 * (hi - lo) * q.w;
      const double x1 = x0 + w, centre = x0 + 0.5 * w;
      Axis at{0, 0, 0, 0};
      for (double c = std::floor(x0) - 1.0; c <= std::ceil(x1) + 1.0; c += 1.0) {
        const double ramp = ramp_integral(x1 - c) - ramp_integral(x0 - c);
        const double mass = kernel_integral(x1 - c) - kernel_integral(x0 - c);
        const double k = kernel(centre - c);
        at.a += ramp * ramp;
        at.b += mass * mass;
        at.a_centre += k * (centre - c) * ramp;
        at.b_centre += k * mass;
      }
      sum.a += weight * at.a, sum.b += weight * at.b, sum.a_centre += weight * at.a_centre;
      sum.b_centre += weight * at.b_centre;
    }
  }
  return {sum.a / (w * w), sum.b / (w * w), sum.a_centre / w, sum.b_centre / w};
}

NoiseFootprintTable::NoiseFootprintTable() {
  for (int i = kTableMinLog2 * kTableStepsPerOctave; i <= kTableMaxLog2 * kTableStepsPerOctave; ++i)
    table_.push_back(axis_exact(std::exp2(double(i) / kTableStepsPerOctave)));
  zero_ = axis_exact(0.0);
  point_variance_ = kGradientSecondMoment * 2.0 * zero_.a * zero_.b;
}

NoiseFootprintTable::Axis NoiseFootprintTable::axis(double w) const {
  const double l = std::log2(std::max(w, 0x1p-1074)) * kTableStepsPerOctave - kTableMinLog2 * kTableStepsPerOctave;
  if (!(l > 0.0)) {  // below 2^-10 cells: linear in w between the point limit and the first entry
    const double f = std::max(w, 0.0) * std::exp2(-double(kTableMinLog2));
    const Axis &p = zero_, &q = table_.front();
    return {p.a + f * (q.a - p.a), p.b + f * (q.b - p.b), p.a_centre + f * (q.a_centre - p.a_centre),
            p.b_centre + f * (q.b_centre - p.b_centre)};
  }
  const double last = double(table_.size() - 1);
  if (l >= last) {  // asymptotes beyond 256 cells: a ~ 1/w^2, b ~ 1/w, a' = 0, b' = 1/w
    const Axis& end = table_.back();
    const double r = std::exp2(double(kTableMaxLog2)) / w;
    return {end.a * r * r, end.b * r, 0.0, 1.0 / w};
  }
  const size_t i = size_t(l);
  const double f = l - double(i);
  const Axis &p = table_[i], &q = table_[i + 1];
  return {p.a + f * (q.a - p.a), p.b + f * (q.b - p.b), p.a_centre + f * (q.a_centre - p.a_centre),
          p.b_centre + f * (q.b_centre - p.b_centre)};
}

double NoiseFootprintTable::box_mean_variance(double w1, double w2) const {
  const Axis x = axis(w1), y = axis(w2);
  return kGradientSecondMoment * (x.a * y.b + x.b * y.a);
}

double NoiseFootprintTable::box_centre_covariance(double w1, double w2) const {
  const Axis x = axis(w1), y = axis(w2);
  return kGradientSecondMoment * (x.a_centre * y.b_centre + x.b_centre * y.a_centre);
}

NoiseFootprint fbm_footprint(const NoiseFootprintTable& table, const NoiseParameters& noise, const Vec2& uv,
                             const Vec2& box_uv) {
  NoiseFootprint out;
  const double V = table.point_variance();
  double amplitude = 1.0;
  for (int o = 0; o < noise.octaves; ++o) {
    const uint32_t px = noise.cells_x << o, py = noise.cells_y << o;
    const double kappa = table.box_centre_covariance(std::abs(box_uv.x()) * px, std::abs(box_uv.y()) * py) / V;
    const double value =
        kappa == 0.0 ? 0.0
                     : periodic_gradient_noise(uv.x() * px, uv.y() * py, px, py, hash_combine(noise.seed, uint32_t(o)));
    out.mean += amplitude * kappa * value;
    out.variance += amplitude * amplitude * V * std::max(0.0, 1.0 - kappa * kappa);
    amplitude *= noise.gain;
  }
  return out;
}

}  // namespace mbk
