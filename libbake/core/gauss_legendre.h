// Gauss-Legendre quadrature: the n nodes and weights on [-1, 1] (exact for polynomials of degree 2n - 1), found by
// Newton's method on the Legendre recurrence in double, and a composite rule over [a, b] in equal panels. Used by
// the numerical integrals of the colour-map filtering distributions (libbake/colormap/).
#pragma once

#include <functional>
#include <vector>

namespace mbk {

struct QuadratureNode {
  double x, w;
};

// n in 1..256; Error(runtime_failure) otherwise.
std::vector<QuadratureNode> gauss_legendre_nodes(int n);

// Nodes and weights of the n-point rule on each of `panels` equal panels of [a, b], in increasing x.
std::vector<QuadratureNode> composite_gauss_legendre(double a, double b, int panels, int n);

}  // namespace mbk
