// Gauss-Legendre quadrature on [a, b]: n nodes integrate polynomials of degree <= 2n - 1 exactly. Used to
// project zonal BRDF lobes onto Legendre polynomials ([Han07] Eq. 7.11: f_l) and by tests that integrate
// over the sphere (nodes in cos(theta), uniform steps in phi).
#pragma once

#include <vector>

namespace mbk {

struct QuadratureRule {
  std::vector<double> nodes, weights;
};

// n >= 1 nodes on [a, b], in increasing order. Nodes by Newton's method on P_n from Tricomi's initial guesses,
// in double (node and weight errors ~1e-15 for n up to a few thousand).
QuadratureRule gauss_legendre(int n, double a = -1.0, double b = 1.0);

}  // namespace mbk
