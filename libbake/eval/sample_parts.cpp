// Long footprints shaded in parts (see sample_parts.h).
#include "libbake/eval/sample_parts.h"

#include <algorithm>
#include <cmath>

namespace mbk {

SampleParts sample_parts(const Vec3& dp_dx, const Vec3& dp_dy, int max_parts) {
  SampleParts parts;
  const int cap = std::clamp(max_parts, 1, kMaxSampleParts);
  if (cap == 1 || !dp_dx.allFinite() || !dp_dy.allFinite()) return parts;
  // G = [dp/dx dp/dy]^T [dp/dx dp/dy] = [[gxx, gxy], [gxy, gyy]]: its eigenvalues are s1^2 >= s2^2 and its major
  // eigenvector is e. s2 = |dp/dx x dp/dy| / s1 avoids the cancellation of thin ellipses.
  const double gxx = dp_dx.squaredNorm(), gyy = dp_dy.squaredNorm(), gxy = dp_dx.dot(dp_dy);
  const double s1_sq = 0.5 * (gxx + gyy + std::hypot(gxx - gyy, 2.0 * gxy));
  const double s1 = std::sqrt(s1_sq), s2 = s1 > 0.0 ? dp_dx.cross(dp_dy).norm() / s1 : 0.0;
  if (!(s1 > 0.0)) return parts;
  const double count = s2 > 0.0 ? std::ceil(s1 / (kPartAnisotropy * s2) - 1e-9) : double(cap);
  parts.count = int(std::clamp(count, 1.0, double(cap)));
  if (parts.count == 1) return parts;
  const Vec2 e = std::abs(gxx - s1_sq) > std::abs(gyy - s1_sq) ? Vec2(gxy, s1_sq - gxx) : Vec2(s1_sq - gyy, gxy);
  const double len = e.norm();
  if (len > 0.0) parts.axis = e / len;
  return parts;
}

Vec2 part_offset(const SampleParts& parts, int k) { return ((k + 0.5) / parts.count - 0.5) * parts.axis; }

void shrink_to_part(const SampleParts& parts, Vec3& ddx, Vec3& ddy) {
  // D' = D (I - (1 - 1/P) e e^T): the differential along e shrinks by 1/P, the one across it is kept.
  const double shrink = 1.0 - 1.0 / parts.count;
  const Vec3 along = parts.axis.x() * ddx + parts.axis.y() * ddy;
  ddx -= shrink * parts.axis.x() * along;
  ddy -= shrink * parts.axis.y() * along;
}

}  // namespace mbk
