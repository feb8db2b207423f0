// uv to the glint target plane, with the v flip (see glint_surface_mapping.h).
#include "libbake/glint/glint_surface_mapping.h"

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

namespace mbk {

Vec2 glint_target_point(const Vec2& uv, uint32_t width, uint32_t height) {
  return Vec2(uv.x() * width, (1.0 - uv.y()) * height);
}

Mat2 glint_tangent_jacobian(const Mat2& target_jacobian, uint32_t width, uint32_t height) {
  Mat2 scale = Mat2::Zero();
  scale(0, 0) = width;
  scale(1, 1) = -double(height);
  return target_jacobian * scale;
}

GlintFootprint glint_probe_footprint(const Vec2& uv, double box_width, uint32_t width, uint32_t height) {
  // Non-finite (grazing) stays non-finite, for footprint_texels() to refuse.
  const double sigma =
      std::isfinite(box_width) ? std::max(box_width / std::sqrt(12.0), kGlintMinFootprintSigma) : box_width;
  return {glint_target_point(uv, width, height), sigma};
}

Mat2 glint_half_vector_slope(const Mat2& steps, const Vec2& duv_dx, const Vec2& duv_dy, double probe_sigma,
                             uint32_t width, uint32_t height) {
  Mat2 m;  // M = diag(W, -H) [duv/dx duv/dy]
  m.col(0) = duv_dx;
  m.col(1) = duv_dy;
  m.row(0) *= double(width);
  m.row(1) *= -double(height);
  if (!m.allFinite() || !steps.allFinite() || !std::isfinite(probe_sigma)) return Mat2::Zero();
  const Eigen::JacobiSVD<Mat2> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Vec2 sigma = svd.singularValues();
  if (!(sigma.x() > 0.0)) return Mat2::Zero();
  const double reach = std::sqrt(12.0) * probe_sigma;  // the probe's box width
  const Vec2 inverse(1.0 / std::max(sigma.x(), reach), 1.0 / std::max(sigma.y(), reach));
  return steps * svd.matrixV() * inverse.asDiagonal() * svd.matrixU().transpose();
}

}  // namespace mbk
