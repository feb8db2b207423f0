// Ground truth for the three colour-map filtering cases ([Heitz13] Eqs. 7, 14, 19): the brute-force averages a
// `--reference` render takes over the samples of a pixel footprint, from the raw (unfiltered) driver values, as plain
// functions of those samples (the renderer chooses and weights the samples; equal weights for a box filter).
// Colours are the colour map's C (piecewise linear, formats/colormap_layout.h) at sigma = 0, never the table's
// filtered rows. Directions in the local frame of the mean surface.
//
// - texture (Eq. 7):   sum_s w_s C(f_s) / sum_s w_s.
// - heights (Eq. 14):  sum_s w_s C(h_s) V(h_s, wo) V(h_s, wi) / sum_s w_s V(h_s, wo), V(h, w) = P_h(h)^Lambda(w)
//   (Eq. 2: Smith's visibility of a Gaussian surface of height deviation sigma_h, P_h its height CDF; the heights
//   are deviations from the surface's mean height and the colour map is read at offset + h).
// - slopes (Eq. 19):   sum_s w_s C(offset + d . s_s) (w_z - s_s . w_xy)_+ / sum_s w_s (w_z - s_s . w_xy)_+.
#pragma once

#include <span>

#include "formats/colormap_layout.h"
#include "libbake/core/eigen.h"

namespace mbk {

struct WeightedValue {
  double value, weight;
};
struct WeightedSlope {
  Vec2 slope;
  double weight;
};

Vec3 reference_texture_colormap(const ColormapCurve& curve, std::span<const WeightedValue> samples);

// Returns the colour with V_bar included (as Eq. 14), 0 when the light is below the horizon or nothing is seen.
Vec3 reference_height_colormap(const ColormapCurve& curve, std::span<const WeightedValue> heights, double sigma_h,
                               double offset, double lambda_o, double lambda_i);

Vec3 reference_slope_colormap(const ColormapCurve& curve, std::span<const WeightedSlope> slopes, const Vec2& direction,
                              double offset, const Vec3& wo);

}  // namespace mbk
