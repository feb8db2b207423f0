// Height-correlated colour filtering numerics (see height_filtering.h).
#include "libbake/colormap/height_filtering.h"

#include <cmath>
#include <limits>
#include <vector>

#include "libbake/core/gauss_legendre.h"

namespace mbk {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const std::vector<QuadratureNode>& height_nodes() {
  static const std::vector<QuadratureNode> nodes = composite_gauss_legendre(-40.0, 40.0, 300, 8);
  return nodes;
}

// Levenberg-Marquardt on two parameters for residuals r_k(a, b) = model(L_k, a, b) - y_k, with the model's
// gradient; from (a, b), keeping b > 0 (the argument of the log must stay positive).
struct ModelValue {
  double value, d_a, d_b;
};
template <typename Model>
std::pair<double, double> fit_two(const std::vector<double>& L, const std::vector<double>& y, double a, double b,
                                  Model model) {
  auto cost = [&](double pa, double pb) {
    double c = 0.0;
    for (size_t k = 0; k < L.size(); ++k) {
      const double r = model(L[k], pa, pb).value - y[k];
      c += r * r;
    }
    return c;
  };
  double damping = 1e-3, current = cost(a, b);
  for (int iteration = 0; iteration < 500; ++iteration) {
    double jaa = 0, jab = 0, jbb = 0, ga = 0, gb = 0;
    for (size_t k = 0; k < L.size(); ++k) {
      const ModelValue m = model(L[k], a, b);
      const double r = m.value - y[k];
      jaa += m.d_a * m.d_a, jab += m.d_a * m.d_b, jbb += m.d_b * m.d_b;
      ga += m.d_a * r, gb += m.d_b * r;
    }
    bool improved = false;
    while (damping < 1e12) {
      const double A = jaa * (1 + damping), B = jab, D = jbb * (1 + damping);
      const double det = A * D - B * B;
      const double da = -(D * ga - B * gb) / det, db = -(A * gb - B * ga) / det;
      const double next_b = b + db;
      if (next_b > 0.0) {
        const double next = cost(a + da, next_b);
        if (next < current) {
          const bool converged = current - next < 1e-15 * current;
          a += da, b = next_b, current = next, damping *= 0.3, improved = true;
          if (converged) return {a, b};
          break;
        }
      }
      damping *= 10.0;
    }
    if (!improved) break;
  }
  return {a, b};
}

std::vector<double> lambda_samples(double lambda_min, double lambda_max, int samples) {
  std::vector<double> L = {0.0};
  for (int k = 0; k < samples; ++k)
    L.push_back(lambda_min * std::pow(lambda_max / lambda_min, samples == 1 ? 0.0 : double(k) / (samples - 1)));
  return L;
}

}  // namespace

// [Heitz13] Eq. (3) with a = mu / (sqrt(2) sigma_s): Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2.
double smith_lambda_gaussian(double cot_theta, double sigma_s) {
  if (!(cot_theta > 0.0)) return kInf;
  if (std::isinf(cot_theta) || !(sigma_s > 0.0)) return 0.0;
  const double a = cot_theta / (std::sqrt(2.0) * sigma_s);
  if (a > 38.0) return 0.0;  // both terms underflow to 0
  return 0.5 * (std::exp(-a * a) / (a * std::sqrt(M_PI)) - std::erfc(a));
}

double smith_lambda(const Vec3& w, const Mat2& slope_covariance) {
  if (!(w.z() > 0.0)) return kInf;
  const double len = std::hypot(w.x(), w.y());
  if (len == 0.0) return 0.0;
  const Vec2 phi(w.x() / len, w.y() / len);
  const double variance = phi.dot(slope_covariance * phi);
  if (!(variance > 0.0)) return 0.0;
  return smith_lambda_gaussian(w.z() / len, std::sqrt(variance));
}

// [Heitz13] Eq. (13).
double averaged_visibility(double lambda_o, double lambda_i) {
  if (std::isinf(lambda_i)) return 0.0;
  if (std::isinf(lambda_o)) return 1.0;  // the limit of (1 + Lo) / (1 + Lo + Li) for finite Li
  return (1.0 + lambda_o) / (1.0 + lambda_o + lambda_i);
}

// [Heitz13] Eqs. (16-18): D(z) proportional to Phi(z)^L phi(z), moments by quadrature (log domain for Phi^L).
HeightMoments height_moments_exact(double lambda_sum, double* raw_second) {
  double mass = 0.0, first = 0.0, second = 0.0;
  std::vector<double> weights;
  weights.reserve(height_nodes().size());
  for (const QuadratureNode& q : height_nodes()) {
    const double log_phi = -0.5 * q.x * q.x;
    const double log_cdf = std::log(0.5 * std::erfc(-q.x / std::sqrt(2.0)));
    const double w = q.w * std::exp(lambda_sum == 0.0 ? log_phi : lambda_sum * log_cdf + log_phi);
    weights.push_back(w);
    mass += w, first += w * q.x, second += w * q.x * q.x;
  }
  const double mean = first / mass;
  double central = 0.0;
  for (size_t k = 0; k < weights.size(); ++k)
    central += weights[k] * (height_nodes()[k].x - mean) * (height_nodes()[k].x - mean);
  if (raw_second) *raw_second = second / mass;
  return {mean, std::sqrt(central / mass)};
}

// [Heitz13] Eqs. (17, 18), in units of sigma_h.
HeightMoments height_moments_fitted(double lambda_sum, const HeightFit& fit) {
  return {fit.alpha_mu * std::log1p(fit.beta_mu * lambda_sum),
          1.0 / (1.0 + fit.alpha_sigma * std::log1p(fit.beta_sigma * lambda_sum))};
}

HeightFilter height_filter(double sigma_h, double lambda_o, double lambda_i, const HeightFit& fit) {
  const double L = lambda_o + lambda_i;
  if (std::isinf(L)) return {averaged_visibility(lambda_o, lambda_i), kInf, 0.0};
  const HeightMoments m = height_moments_fitted(L, fit);
  return {averaged_visibility(lambda_o, lambda_i), sigma_h * m.mean, sigma_h * m.stddev};
}

HeightFitReport height_fit_residuals(const HeightFit& fit, double lambda_min, double lambda_max, int samples) {
  HeightFitReport r;
  r.fit = fit;
  const std::vector<double> L = lambda_samples(lambda_min, lambda_max, samples);
  double mean_squares = 0.0, stddev_squares = 0.0;
  for (double l : L) {
    const HeightMoments exact = height_moments_exact(l), fitted = height_moments_fitted(l, fit);
    const double dm = std::abs(fitted.mean - exact.mean), ds = std::abs(fitted.stddev - exact.stddev);
    r.mean_max_residual = std::max(r.mean_max_residual, dm);
    r.stddev_max_residual = std::max(r.stddev_max_residual, ds);
    mean_squares += dm * dm, stddev_squares += ds * ds;
  }
  r.mean_rms_residual = std::sqrt(mean_squares / double(L.size()));
  r.stddev_rms_residual = std::sqrt(stddev_squares / double(L.size()));
  return r;
}

HeightFitReport refit_height_moments(double lambda_min, double lambda_max, int samples) {
  const std::vector<double> L = lambda_samples(lambda_min, lambda_max, samples);
  std::vector<double> means, stddevs;
  for (double l : L) {
    const HeightMoments m = height_moments_exact(l);
    means.push_back(m.mean);
    stddevs.push_back(m.stddev);
  }
  HeightFit fit;
  std::tie(fit.alpha_mu, fit.beta_mu) = fit_two(L, means, fit.alpha_mu, fit.beta_mu, [](double l, double a, double b) {
    return ModelValue{a * std::log1p(b * l), std::log1p(b * l), a * l / (1.0 + b * l)};
  });
  std::tie(fit.alpha_sigma, fit.beta_sigma) =
      fit_two(L, stddevs, fit.alpha_sigma, fit.beta_sigma, [](double l, double a, double b) {
        const double g = 1.0 / (1.0 + a * std::log1p(b * l));
        return ModelValue{g, -g * g * std::log1p(b * l), -g * g * a * l / (1.0 + b * l)};
      });
  return height_fit_residuals(fit, lambda_min, lambda_max, samples);
}

}  // namespace mbk
