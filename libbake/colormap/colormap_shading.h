// [Heitz13] Eric Heitz, Derek Nowrouzezahrai, Pierre Poulin, Fabrice Neyret. Filtering Color Mapped Textures and
// Surfaces. I3D 2013. The technique's entry point: what an evaluator shader does per pixel.
//
// Implemented (libbake/colormap/): Sec. 4.2 (the prefiltered table of Eq. 10, colormap_table.h; footprint moments of
// tabulated drivers, moment_pyramid.h, and of procedural noise, noise_statistics.h), Sec. 5.1 (Eqs. 2, 3, 13-18,
// height_filtering.h), Sec. 5.2 (Eqs. 19-20 with our derivation of D_s, slope_filtering.h), Sec. 6 (below), and the
// brute-force ground truth of each case (colormap_reference.h). Deviations, each tied to a test:
// - The fitted constants of Eqs. (17, 18) are refit (kRefitHeightConstants): the paper's are 3x (mean) and 9x
//   (sigma) further from the exact moments (HeightDistribution.PaperConstantsResidualAndRefit).
// - Eq. (18) is read as the central second moment, not the raw one it prints
//   (HeightDistribution.PaperSigmaIsTheCentralMoment_Erratum); Eq. (13)'s denominator integrand needs p_h.
// - D_s is the exact moment match of p(s) (w_z - s . w_xy)_+, derived in slope_filtering.h (the paper's derivation
//   is in a supplement we do not have) (SlopeFiltering.MomentsMatchBruteForce_HeadOnToGrazing).
// - Moments of tabulated drivers are stored about the driver's mean, so the variance survives float storage
//   (MomentPyramid.FarFromZeroDriverKeepsItsVariance_Shift).
// - The footprint mean of noise is the best linear predictor from the centre value (noise_statistics.h); the paper
//   only says the standard deviation is tabulated per level
//   (NoiseStatistics.FbmFootprintMatchesSupersampledFootprints).
//
// Conventions: directions in the local frame of the mean surface (z out, unit length); colours linear RGB. The
// per-pixel functions below are plain functions over a prefiltered table (formats/colormap_layout.h), so that a
// renderer needs this file, the table and the statistics helpers only.
//
// Three ways to colour a pixel whose driver f has mean m and standard deviation sigma over the footprint:
// - naive:    C(m), the colour map of the MIP-mapped driver (what is usually done; the table's sigma = 0 row);
// - texture:  E[C(f)], f ~ N(m, sigma^2), view-independent (Sec. 4.2, Eq. 10): one lookup at (m, sigma);
// - filtered: for surface-correlated maps, the view- and light-dependent filtering distributions of Sec. 5
//             (heights: Eqs. 13-18; slopes: Eqs. 19-20); for C_0 (uncorrelated) it equals `texture`.
//
// Sec. 6: colours built from the three cases combine as
//   linear  C = k0 C_0 + k1 C_h + k2 C_s:  I = L rho [k0 C0_bar V_bar + k1 Ch_bar + k2 Cs_bar V_bar],
//   product C = C_0 C_h C_s:               I = L C0_bar Ch_bar Cs_bar  (the paper's form, which drops V_bar and rho),
// where Ch_bar already carries V_bar (Eq. 14). combine_colormaps returns the bracket (linear) or the product; the
// caller multiplies by its lighting.
#pragma once

#include "formats/colormap_layout.h"
#include "libbake/colormap/height_filtering.h"
#include "libbake/colormap/slope_filtering.h"
#include "libbake/core/eigen.h"

namespace mbk {

enum class ColormapFiltering { naive, texture, filtered };

// C_0 at a footprint with driver statistics (mean, sigma).
Vec3 texture_colormap(const ColormapTable& table, double mean, double sigma, ColormapFiltering mode);

// The microsurface of Secs. 5.1-5.2: Gaussian heights N(0, sigma_h^2) (in the colour map's driver units; the colour
// map is read at height + height_offset) and Gaussian slopes N(mean_slope, slope_covariance).
struct Microsurface {
  double sigma_h = 0.1, height_offset = 0.5;
  SlopeGaussian slopes;
};

// Ch_bar (Eq. 14) and V_bar (Eq. 13) for view wo and light wi. noise_mean / noise_variance perturb the heights
// (Sec. 5.1, last paragraph: C(h + r)). naive: C(offset + noise_mean) with V_bar 1; texture: the view-independent
// lookup at (offset + noise_mean, sqrt(sigma_h^2 + noise_variance)) with V_bar 1.
struct HeightColormap {
  Vec3 color = Vec3::Zero();  // includes the visibility factor V_bar, as Eq. (14) does
  double visibility = 1.0;    // V_bar
};
HeightColormap height_colormap(const ColormapTable& table, const Microsurface& surface, const Vec3& wo, const Vec3& wi,
                               ColormapFiltering mode, double noise_mean = 0.0, double noise_variance = 0.0,
                               const HeightFit& fit = kRefitHeightConstants);

// Cs_bar (Eq. 20) for C(offset + d . s), d a unit tangent direction. naive: C(offset + d . mean slope); texture: the
// lookup at the footprint's slope statistics, ignoring the view.
Vec3 slope_colormap(const ColormapTable& table, const Microsurface& surface, const Vec2& direction, double offset,
                    const Vec3& wo, ColormapFiltering mode);

struct ColormapTerms {
  Vec3 c0 = Vec3::Ones(), ch = Vec3::Ones(), cs = Vec3::Ones();  // C0_bar, Ch_bar (with V_bar), Cs_bar
  double visibility = 1.0;                                       // V_bar
};
struct ColormapWeights {
  bool product = false;                 // C = C_0 C_h C_s instead of the linear combination
  double k0 = 1.0, k1 = 0.0, k2 = 0.0;  // linear weights
};
Vec3 combine_colormaps(const ColormapTerms& terms, const ColormapWeights& weights);

}  // namespace mbk
