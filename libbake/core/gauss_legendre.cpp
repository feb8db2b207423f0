// Gauss-Legendre nodes and composite rules (see gauss_legendre.h).
#include "libbake/core/gauss_legendre.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"

namespace mbk {

std::vector<QuadratureNode> gauss_legendre_nodes(int n) {
  if (n < 1 || n > 256) throw Error(ExitCode::runtime_failure, "internal: Gauss-Legendre order outside 1..256");
  std::vector<QuadratureNode> nodes(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p = 1.0, previous = 0.0;  // P_k(z), P_{k-1}(z)
      for (int k = 1; k <= n; ++k) {
        const double older = previous;
        previous = p;
        p = ((2.0 * k - 1.0) * z * previous - (k - 1.0) * older) / k;
      }
      derivative = n * (z * p - previous) / (z * z - 1.0);
      const double step = p / derivative;
      z -= step;
      if (std::abs(step) < 1e-16) break;
    }
    nodes[size_t(i)] = {z, 2.0 / ((1.0 - z * z) * derivative * derivative)};
  }
  std::sort(nodes.begin(), nodes.end(), [](const QuadratureNode& a, const QuadratureNode& b) { return a.x < b.x; });
  return nodes;
}

std::vector<QuadratureNode> composite_gauss_legendre(double a, double b, int panels, int n) {
  const std::vector<QuadratureNode> rule = gauss_legendre_nodes(n);
  std::vector<QuadratureNode> out;
  out.reserve(size_t(panels) * rule.size());
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (const QuadratureNode& q : rule) out.push_back({mid + 0.5 * h * q.x, 0.5 * h * q.w});
  }
  return out;
}

}  // namespace mbk
