// Gauss-Legendre quadrature (libbake/core/gauss_legendre.h): the n-point rule integrates polynomials of degree
// 2n - 1 exactly, weights sum to the interval length, nodes are sorted and symmetric; the composite rule
// integrates exp to double precision; orders outside 1..4096 are refused.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/error.h"
#include "libbake/core/gauss_legendre.h"

namespace mbk {
namespace {

TEST(GaussLegendre, ExactForPolynomialsOfDegree2nMinus1) {
  for (int n : {1, 2, 5, 8, 24, 64}) {
    const auto nodes = gauss_legendre_nodes(n);
    ASSERT_EQ(nodes.size(), size_t(n));
    for (int degree = 0; degree <= 2 * n - 1; degree += (n > 8 ? 7 : 1)) {
      double sum = 0.0;
      for (const QuadratureNode& q : nodes) sum += q.w * std::pow(q.x, degree);
      const double exact = degree % 2 ? 0.0 : 2.0 / (degree + 1);
      EXPECT_NEAR(sum, exact, 1e-13) << n << " points, degree " << degree;
    }
    for (size_t i = 0; i < nodes.size(); ++i) {
      if (i > 0) {
        EXPECT_LT(nodes[i - 1].x, nodes[i].x);
      }
      EXPECT_NEAR(nodes[i].x, -nodes[nodes.size() - 1 - i].x, 1e-15);
      EXPECT_GT(nodes[i].w, 0.0);
    }
  }
}

TEST(GaussLegendre, CompositeRuleIntegratesExp) {
  double sum = 0.0;
  for (const QuadratureNode& q : composite_gauss_legendre(-1.0, 3.0, 10, 8)) sum += q.w * std::exp(q.x);
  EXPECT_NEAR(sum, std::exp(3.0) - std::exp(-1.0), 1e-13);
}

TEST(GaussLegendre, RefusesOrdersOutOfRange) {
  EXPECT_THROW(gauss_legendre_nodes(0), Error);
  EXPECT_THROW(gauss_legendre_nodes(4097), Error);
}

}  // namespace
}  // namespace mbk
