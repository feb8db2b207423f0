// Per-pixel colour-map filtering for shaders (see colormap_shading.h).
#include "libbake/colormap/colormap_shading.h"

#include <cmath>

namespace mbk {
namespace {

Vec3 to_vec(const std::array<double, 3>& c) { return Vec3(c[0], c[1], c[2]); }

}  // namespace

Vec3 texture_colormap(const ColormapTable& table, double mean, double sigma, ColormapFiltering mode) {
  return to_vec(table.lookup(mean, mode == ColormapFiltering::naive ? 0.0 : sigma));
}

HeightColormap height_colormap(const ColormapTable& table, const Microsurface& surface, const Vec3& wo, const Vec3& wi,
                               ColormapFiltering mode, double noise_mean, double noise_variance, const HeightFit& fit) {
  const double centre = surface.height_offset + noise_mean;
  if (mode == ColormapFiltering::naive) return {to_vec(table.lookup(centre, 0.0)), 1.0};
  if (mode == ColormapFiltering::texture)
    return {to_vec(table.lookup(centre, std::sqrt(surface.sigma_h * surface.sigma_h + noise_variance))), 1.0};
  // [Heitz13] Eqs. (13, 14, 17, 18): V_bar times one lookup at the shifted, narrowed height distribution.
  const double lo = smith_lambda(wo, surface.slopes.covariance), li = smith_lambda(wi, surface.slopes.covariance);
  const HeightFilter f = height_filter(surface.sigma_h, lo, li, fit);
  if (f.visibility == 0.0) return {Vec3::Zero(), 0.0};
  const double sigma = std::sqrt(f.stddev * f.stddev + noise_variance);
  return {f.visibility * to_vec(table.lookup(centre + f.mean, sigma)), f.visibility};
}

Vec3 slope_colormap(const ColormapTable& table, const Microsurface& surface, const Vec2& direction, double offset,
                    const Vec3& wo, ColormapFiltering mode) {
  if (mode == ColormapFiltering::naive) return to_vec(table.lookup(offset + direction.dot(surface.slopes.mean), 0.0));
  // [Heitz13] Eq. (20) with the moment-matched D_s (slope_filtering.h); `texture` keeps the unweighted slopes.
  const SlopeGaussian seen =
      mode == ColormapFiltering::filtered ? visible_slope_distribution(surface.slopes, wo).gaussian : surface.slopes;
  const DriverStatistics s = slope_driver(seen, direction);
  return to_vec(table.lookup(offset + s.mean, s.stddev));
}

// [Heitz13] Sec. 6.
Vec3 combine_colormaps(const ColormapTerms& t, const ColormapWeights& w) {
  if (w.product) return t.c0.cwiseProduct(t.ch).cwiseProduct(t.cs);
  return w.k0 * t.visibility * t.c0 + w.k1 * t.ch + w.k2 * t.visibility * t.cs;
}

}  // namespace mbk
