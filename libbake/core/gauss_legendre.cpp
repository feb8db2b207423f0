// Gauss-Legendre nodes and weights (see gauss_legendre.h).
#include "libbake/core/gauss_legendre.h"

#include <cmath>
#include <numbers>
#include <string>

#include "formats/error.h"

namespace mbk {

QuadratureRule gauss_legendre(int n, double a, double b) {
  if (n < 1) throw Error(ExitCode::runtime_failure, "internal: Gauss-Legendre rule of " + std::to_string(n) + " nodes");
  QuadratureRule rule;
  rule.nodes.resize(size_t(n));
  rule.weights.resize(size_t(n));
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // The i-th largest root of P_n, refined by Newton on P_n(x) (three-term recurrence) and P_n'(x).
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1.0;
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / derivative;
      x -= dx;
      if (std::abs(dx) <= 1e-16) break;
    }
    const double w = 2.0 / ((1.0 - x * x) * derivative * derivative);
    rule.nodes[size_t(n - 1 - i)] = mid + half * x;
    rule.nodes[size_t(i)] = mid - half * x;
    rule.weights[size_t(i)] = rule.weights[size_t(n - 1 - i)] = half * w;
  }
  return rule;
}

}  // namespace mbk
