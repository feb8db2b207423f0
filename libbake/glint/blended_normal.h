// The point query of the infinite, non-repeating microstructure ([Wang20] Sec. 4.2 and appendix A.2): the
// normal components n(u) = (n_x, n_y) at a target point u and their analytic Jacobian J(u) = dn/du, blended
// from the four example patches of target_patch_grid.h, each read by example_bilinear.h. Each channel c is
// blended separately; with corner samples I_k, their gradients g_k = dI_k/du (de/du is the identity), weights
// w_k and weight gradients dw_k (k = 0..3):
// - linear ([Wang20] Eq. 4):     n = L = sum w_k I_k,      dn = sum (dw_k I_k + w_k g_k).
// - variance ([Wang20] Eq. 5):   n = (L - m) / W + m,  m = the example channel's mean (over all texels),
//                                W = ||w||_2,  dW = sum w_k dw_k / W,  dn = dL / W - (L - m) dW / W^2.
// - histogram ([Wang20] Eq. 6):  n = G^-1(Z), Z = sum w_k Z_k / W (the variance blend in the Gaussian space,
//                                mean 0), where Z_k is the STANDARDIZED example read bilinearly: each texel is
//                                standardized once, G(texel), and Z_k, dZ_k = g_k interpolate those values
//                                ([Heitz18] Sec. 3: the Gaussian example is what is sampled),
//                                dn = (G^-1)'(Z) (sum (dw_k Z_k + w_k dZ_k) / W - Z dW / W),
//                                G, G^-1 and (G^-1)' through the standardization knots (lut_lookup.h:
//                                derivatives are the slopes of the interpolants' segments).
//                                Deviation from reading G(I_k) of the bilinear example: at an atom (a value
//                                shared by many texels) G rises by ~2 within a few ulps, so G(bilinear I) jumps
//                                right next to every atom texel's centre and is flat on it; elements linearized
//                                at texel centres (glint_pndf.h) then cannot follow the field and the P-NDF
//                                loses its tail mass. The standardized example is piecewise bilinear like the
//                                other modes' (test: GlintPndfTailMass.*). At texel centres the two agree.
// - none ([Wang20] Sec. 6, flakes): the single patch of the NEAREST grid vertex (the corner with the largest
//                                weight: f_0 >= 1/2 picks i + 1, likewise f_1), n = I_k, dn = g_k.
// W >= 1/2 everywhere (its minimum, at a patch centre), so nothing divides by zero.
// Seams and kinks (measure zero): J jumps across target patch borders (the weights' kinks; for `none` also
// where the nearest vertex changes, f = 1/2, where n itself jumps), across texel-centre lines of each corner's
// example point (bilinear kinks), and, for `histogram`, where Z crosses a knot of G^-1. On them the value
// is continuous (except `none`) and J is the one-sided derivative of the piece on the +u side (every floor
// above picks that piece; the lookup picks the segment starting at the knot).
#pragma once

#include <cstdint>
#include <string_view>

#include "libbake/core/eigen.h"
#include "libbake/glint/example_bilinear.h"
#include "formats/standardization_lut.h"
#include "libbake/glint/target_patch_grid.h"
#include "libbake/image/normal_map.h"

namespace mbk {

enum class GlintBlendMode { none, linear, variance, histogram };

// What a point query needs; it references (does not copy) the example and the LUT, which must outlive it.
class GlintPointQuery {
 public:
  // Throws Error(bad_command_line) for a bad patch side (target_patch_grid.h), Error(invalid_input) for an
  // empty example or, for `histogram`, a missing LUT.
  GlintPointQuery(const NormalMap& example, uint32_t patch_side, uint32_t seed, GlintBlendMode mode,
                  const StandardizationLut* lut = nullptr);

  const NormalMap& example() const { return *example_; }
  const StandardizationLut* lut() const { return lut_; }
  const TargetPatchGrid& grid() const { return grid_; }
  GlintBlendMode mode() const { return mode_; }
  const Vec2& example_mean() const { return mean_; }  // (mean n_x, mean n_y) over the example's texels
  // What the corners read bilinearly: the normal components, or for `histogram` their standardized values.
  const ExampleChannels& blended_channels() const { return channels_; }

  // n(u) and J(u) = dn/du: rows n_x, n_y; columns d/du_0, d/du_1 (texel units, target_patch_grid.h).
  // `gaussian`, when given and the mode is `histogram`, receives the blend before G^-1: z(u) and dz/du, so
  // that n = G^-1(z) per channel (the P-NDF measures how G^-1 bends over an element's range of z).
  NormalSample evaluate(const Vec2& u, NormalSample* gaussian = nullptr) const;

 private:
  const NormalMap* example_;
  TargetPatchGrid grid_;
  GlintBlendMode mode_;
  const StandardizationLut* lut_;
  Vec2 mean_;
  ExampleChannels channels_;
};

}  // namespace mbk
