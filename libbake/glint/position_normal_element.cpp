// One position-normal element through a Gaussian footprint ([Yan16], [Wang20] Eqs. 1-3): see
// position_normal_element.h.
#include "libbake/glint/position_normal_element.h"

#include <cmath>
#include <numbers>

namespace mbk {
namespace {

// Two independent N(0, 1) numbers from two uniforms in [0, 1) (Box-Muller; 1 - u1 is in (0, 1]).
Vec2 standard_normal_pair(double u1, double u2) {
  const double radius = std::sqrt(-2.0 * std::log(1.0 - u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  return Vec2(radius * std::cos(angle), radius * std::sin(angle));
}

}  // namespace

double element_footprint_integral(const PositionNormalElement& element, const GlintFootprint& footprint, double sigma_r,
                                  const Vec2& s) {
  const double ip = 1.0 / (footprint.sigma * footprint.sigma), ir = 1.0 / (sigma_r * sigma_r);
  const Vec2 d = element.center - footprint.center;
  const Vec2 r = s - element.n;
  const Mat2& J = element.jacobian;
  // A = c I + ir J^T J with c = ip + 1 / sigma_h^2, b = -ip d + ir J^T r. Its determinant and A^-1 b without
  // cancellation, even when J is huge along one direction (next to an atom of the standardization, where G is
  // steep: |J| ~ 1e11 made A00 A11 - A01^2 come out 0 or negative): for 2 x 2 matrices adj(A) = tr(A) I - A and
  // adj(J^T J) = adj(J) adj(J)^T, so
  //   det A = c^2 + c ir |J|_F^2 + ir^2 det(J)^2,     A^-1 b = (c b + ir adj(J) adj(J)^T b) / det A,
  // sums of non-negative terms but for det(J) and the last product, whose entries are J's own.
  const double c = ip + 1.0 / (element.sigma_h * element.sigma_h);
  const Vec2 b = -ip * d + ir * J.transpose() * r;
  const double e = ip * d.squaredNorm() + ir * r.squaredNorm();
  const double det_j = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
  const double det = c * c + c * ir * J.squaredNorm() + ir * ir * det_j * det_j;
  Mat2 adj_j;
  adj_j << J(1, 1), -J(0, 1), -J(1, 0), J(0, 0);
  const Vec2 a_inv_b = (c * b + ir * (adj_j * (adj_j.transpose() * b))) / det;
  const double exponent = std::max(0.0, e - b.dot(a_inv_b));  // >= 0 in exact arithmetic
  return 2.0 * std::numbers::pi / std::sqrt(det) * std::exp(-0.5 * exponent);
}

double element_footprint_mass(const Vec2& element_center, double sigma_h, const GlintFootprint& footprint,
                              double sigma_r) {
  const double sp2 = footprint.sigma * footprint.sigma, sh2 = sigma_h * sigma_h;
  const double se2 = sp2 * sh2 / (sp2 + sh2);
  const double d2 = (element_center - footprint.center).squaredNorm();
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return kTwoPi * sigma_r * sigma_r * kTwoPi * se2 * std::exp(-0.5 * d2 / (sp2 + sh2));
}

Vec2 sample_element_normal(const PositionNormalElement& element, const GlintFootprint& footprint, double sigma_r,
                           const std::array<double, 4>& uniforms) {
  const double sp2 = footprint.sigma * footprint.sigma, sh2 = element.sigma_h * element.sigma_h;
  const Vec2 mean = (sh2 * footprint.center + sp2 * element.center) / (sp2 + sh2);
  const double se = std::sqrt(sp2 * sh2 / (sp2 + sh2));
  const Vec2 u = mean + se * standard_normal_pair(uniforms[0], uniforms[1]);
  return element.n + element.jacobian * (u - element.center) + sigma_r * standard_normal_pair(uniforms[2], uniforms[3]);
}

}  // namespace mbk
