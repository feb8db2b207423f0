// The evaluator side of the colour-map effects `colormap`, `colormap-height` and `colormap-slope` ([Heitz13]
// Filtering Color Mapped Textures and Surfaces, I3D 2013; bake side libbake/scene/effect_colormap.cpp). Each
// computes the material's albedo and wraps `request.base`, which shades with a copy of the BRDF carrying it.
//
// Filtered mode reads the effect's assets (the prefiltered table, kind `colormap`; the driver's moment pyramid,
// kind `moments`, when the driver is an image) and takes the driver's statistics over the pixel footprint:
//   - image driver: trilinear lookup of (f, f^2) at the footprint's LOD (uv_footprint.h's isotropic rule);
//   - noise driver: fbm_footprint() over the footprint's axis-aligned bounding box in uv
//     (|du/dx| + |du/dy|, |dv/dx| + |dv/dy|);
// then, with the scene option `mode`:
//   naive     C(mean f) (C(offset + d . mean slope) for slopes), what a renderer does without the paper;
//   filtered  colormap: E[C(f)] under N(mean, sigma^2) (Eq. 10); colormap-height: V_bar C_h_bar (Eqs. 13-18)
//             with the driver's statistics added to the heights; colormap-slope: C_s_bar (Eq. 20) with the
//             moment-matched visible slope distribution (slope_filtering.h).
// Sec. 6: the colour-map effects of one material combine into one albedo (the second and third join the first's
// shader), with the scene options `combine` (the same in all of them) and `weight` (kappa):
//   linear   albedo = k0 C0_bar V_bar + k1 C_h_bar + k2 C_s_bar V_bar (k: the effects' weights; an absent case
//            weighs 0; V_bar is the height effect's visibility, 1 without one), the paper's I / (L rho);
//   product  albedo = C0_bar C_h_bar C_s_bar (absent cases are 1; weights unused), the paper's form.
// A material with one colour-map effect gets weight * its term (weight 1: the term itself; product takes no
// weights). The height and slope effects of one material must give the same slope_sigma (one microsurface), and
// the colour-map effects come after every other effect of the material (effect_registry.h, sets_albedo). In both
// forms the albedo carries the colour, so the Lambertian factor (the paper's rho) stays in the shading; the
// paper's product form drops it, which only scales the image by the constant rho.
// The light direction w_i of the height case is the first directional light, else the first point light, else
// the surface normal (distant light only).
//
// Reference mode reads no assets: it evaluates C on the raw driver at the exact point (the image bilinearly at
// level 0, the noise itself) and integrates the unresolved microsurface numerically at that point: heights
// (Eq. 14 with the exact Smith visibility; its denominator integrates the whole height law, so it does not
// depend on the driver) and slopes (Eq. 19), by Gauss-Legendre quadrature (heights: 256 nodes over +-8
// sigma_h; slopes: a 48 x 48 grid over +-6 sigma; colormap_reference.h), combined the same way with the exact
// V_bar at the point. The renderer averages the rays of the pixel, which filters the driver.
#pragma once

#include "libbake/eval/effect_shaders.h"

namespace mbk {

ShaderPtr colormap_effect_shader(const EffectShaderRequest& request);
ShaderPtr colormap_height_effect_shader(const EffectShaderRequest& request);
ShaderPtr colormap_slope_effect_shader(const EffectShaderRequest& request);

}  // namespace mbk
