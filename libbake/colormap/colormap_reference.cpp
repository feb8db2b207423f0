// Brute-force colour-map filtering over footprint samples (see colormap_reference.h).
#include "libbake/colormap/colormap_reference.h"

#include <algorithm>
#include <cmath>

namespace mbk {
namespace {

Vec3 at(const ColormapCurve& curve, double x) {
  const auto c = curve.at(x);
  return Vec3(c[0], c[1], c[2]);
}

// P_h(h)^Lambda in the log domain (Lambda may be 0 where P_h underflows, or infinite).
double smith_visibility(double h, double sigma_h, double lambda) {
  if (lambda == 0.0) return 1.0;
  const double cdf = 0.5 * std::erfc(-h / (std::sqrt(2.0) * sigma_h));
  if (std::isinf(lambda)) return cdf >= 1.0 ? 1.0 : 0.0;
  return cdf > 0.0 ? std::exp(lambda * std::log(cdf)) : 0.0;
}

}  // namespace

// [Heitz13] Eq. (7).
Vec3 reference_texture_colormap(const ColormapCurve& curve, std::span<const WeightedValue> samples) {
  Vec3 sum = Vec3::Zero();
  double weight = 0.0;
  for (const WeightedValue& s : samples) {
    sum += s.weight * at(curve, s.value);
    weight += s.weight;
  }
  return weight > 0.0 ? Vec3(sum / weight) : Vec3::Zero();
}

// [Heitz13] Eq. (14), first line, with Eq. (2) for V.
Vec3 reference_height_colormap(const ColormapCurve& curve, std::span<const WeightedValue> heights, double sigma_h,
                               double offset, double lambda_o, double lambda_i) {
  Vec3 sum = Vec3::Zero();
  double seen = 0.0;
  for (const WeightedValue& s : heights) {
    const double vo = smith_visibility(s.value, sigma_h, lambda_o), vi = smith_visibility(s.value, sigma_h, lambda_i);
    sum += s.weight * vo * vi * at(curve, offset + s.value);
    seen += s.weight * vo;
  }
  return seen > 0.0 ? Vec3(sum / seen) : Vec3::Zero();
}

// [Heitz13] Eq. (19), C_s_bar: projected-area weights per unit footprint area (slope_filtering.h).
Vec3 reference_slope_colormap(const ColormapCurve& curve, std::span<const WeightedSlope> slopes, const Vec2& direction,
                              double offset, const Vec3& wo) {
  Vec3 sum = Vec3::Zero();
  double area = 0.0;
  for (const WeightedSlope& s : slopes) {
    const double w = s.weight * std::max(0.0, wo.z() - s.slope.x() * wo.x() - s.slope.y() * wo.y());
    sum += w * at(curve, offset + direction.dot(s.slope));
    area += w;
  }
  return area > 0.0 ? Vec3(sum / area) : Vec3::Zero();
}

}  // namespace mbk
