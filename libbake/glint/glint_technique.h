// Glints from an example normal map with constant storage: the technique block of libbake/glint/.
//
// Papers (keys in libbake/REFERENCES.md):
// - [Wang20] Beibei Wang, Milos Hasan, Nicolas Holzschuch, Ling-Qi Yan. Example-Based Microstructure
//   Rendering with Constant Storage. ACM Transactions on Graphics 39(5), 2020.
// - [Heitz18] Eric Heitz, Fabrice Neyret. High-Performance By-Example Noise using a Histogram-Preserving
//   Blending Operator. Proc. ACM Comput. Graph. Interact. Tech. (HPG) 1(2), 2018.
// - [Yan16] Ling-Qi Yan, Milos Hasan, Steve Marschner, Ravi Ramamoorthi. Position-Normal Distributions for
//   Efficient Rendering of Specular Microstructure. ACM Transactions on Graphics 35(4), 2016.
//
// A small example normal map drives an infinite, non-repeating microstructure: every point of the surface is
// blended from four example patches ([Wang20] Sec. 4.2, blending of [Heitz18]); two baked tables make its
// glints renderable: the standardization LUTs of histogram-preserving blending ([Wang20] Eq. 6, asset kind
// `lut`) and the RMQ min/max tables of the range queries ([Wang20] Sec. 4.4, asset kind `rmq`).
//
// Implemented so far:
// - Standardization knots (`microbake lut`, asset kind `lut`, id 10): standard_normal.h (exact Phi and
//   Phi^-1), empirical_standardization.h (the exact transform G of one channel and its inverse),
//   standardization_sampling.h (knots (x, G(x)) at both grids and the atoms, read forward and back),
//   lut_asset.h (the bake and its error statistics). What reads the asset lives in formats/, the one home of
//   evaluator-side lookups (a renderer needs formats/ only): formats/lut_layout.h (layout and grid positions,
//   shared with `validate`), formats/lut_lookup.h (the one lookup convention: KnotInterpolant),
//   formats/standardization_lut.h (the knots of an asset, as the evaluator reads them).
// - RMQ min/max tables (`microbake rmq`, asset kind `rmq`, id 3; [Wang20] Sec. 4.4, 5.1, Alg. 1-2):
//   element_normal_bounds.h (leaf intervals: the reach of a texel's sub-elements), rmq_table.h (the sparse table,
//   quantized; its deviations), rmq_atom_range.h (the quantization range that stores flat ground exactly),
//   rmq_asset.h (the bake); the layout, the conservative quantizer and the O(1) rectangle
//   query the evaluator uses live in formats/ (rmq_layout.h, rmq_quantization.h, rmq_query.h), which is all a renderer
//   needs to read the asset.
// - Point query of the infinite microstructure ([Wang20] Sec. 4.2, Eqs. 4-6, appendix A.2): target_patch_grid.h
//   (target patches of side P / 2, example patches of side P chosen by an integer hash of the grid vertex,
//   bilinear weights), example_bilinear.h (the example read bilinearly between texel centres, clipped at the
//   border, with its exact derivative), blended_normal.h (GlintPointQuery: n(u) and its analytic Jacobian for
//   the blend modes none, linear, variance and histogram, including the derivatives of the weights, of W and
//   of the standardization).
// - Range query ([Wang20] Sec. 4.3-4.5): blended_range.h (conservative bounds of the blended normal over a
//   node of target texels from the four example patches' RMQ ranges pushed through the monotone blend, the
//   weights and W = ||w|| bounded over the whole node; and each target texel's exact element bounds).
// - P-NDF ([Wang20] Eqs. 1-3, Alg. 3, Sec. 5.2-5.3): position_normal_element.h (one element through a Gaussian
//   footprint in closed form, its mass, a sample), glint_pndf.h (D_P by traversal, by brute force, and
//   importance sampling; its truncation rules), glint_surface_mapping.h (uv and pixel footprints to the target
//   plane, with the v flip: target u_1 runs down the rows, tangent +v up), glint_surface.h (a glint material
//   assembled from the example and its two assets read through formats/: what the evaluator's shaders call).
//
// Conventions shared by every glint table (they all describe the same example; the evaluator reads them all):
// - The example is a NormalMap (libbake/image/normal_map.h: +Y, row 0 at the top, texel (x, row)). Glints use
//   the "normal components" n_x, n_y of the unit normal ([Wang20]: z is dropped), each blended separately.
// - Borders: the example is NOT assumed tileable. Example patches always lie inside the example, so tables
//   CLIP at the border: a square or a difference stencil that would leave the image uses only the texels
//   inside it, and derivatives at the border use one-sided differences.
// - Position-normal element ([Yan16], [Wang20] Sec. 3.1): spatial sigma_h = 1.5 / sqrt(12) texels, spatial
//   cut-off 3 sigma_h, normal cut-off 4 sigma_r (sigma_r, the intrinsic roughness, is applied at query time,
//   never baked), Gaussian pixel footprint cut-off 3 sigma. The P-NDF evaluates each texel's element as 2 x 2
//   sub-elements of sigma_h / 2 (deviation below), truncated by the texel's element box.
// - Sub-element Jacobians J = d(n_x, n_y) / d(x, y) in texel units are the bilinear field's own, inside a cell;
//   a texel's element box (RMQ leaf) holds its four sub-elements (element_normal_bounds.h).
// - Standardization ([Heitz18] Sec. 3): the Gaussian is the STANDARD normal N(0, 1). [Heitz18] use mean 0.5
//   and standard deviation 1/6; the two differ by an affine map, which the variance-preserving blend
//   ([Wang20] Eq. 5) commutes with, so blended results are identical.
// - Determinism: identical bytes whatever --threads (per-index results, serial reductions).
//
// Deviations from the papers and their public code, each tied to the test that holds it:
// - Deviation [Heitz18]: ranks are MID-RANKS, so equal example values get one and the same Gaussian value and
//   a constant channel maps to the constant 0 with zero derivative; sorting with arbitrary tie-breaking would
//   map equal inputs to different outputs (tests: EmpiricalStandardization.TiesShareOneGaussianValue,
//   StandardizationLut.ConstantAndTwoValuedChannels).
// - Deviation [Heitz18]: G is continuous between example values (the mid-rank CDF interpolated linearly between
//   consecutive distinct values, then Phi^-1), so G^-1(G(x)) = x exactly for the transform (test:
//   EmpiricalStandardization.InverseUndoesForward).
// - Deviation [Heitz18], [Wang20]: no uniform forward and inverse tables but one set of knots (x, G(x)), at a
//   uniform x grid, at G^-1 of a uniform z grid and at every atom (a value of >= N / size texels), read as
//   (x, z) forward and (z, x) inverse: the two maps are exact inverses, G is exact at atoms, and each map is
//   within one grid step of the exact one, so the blended microstructure is the exact blend's whatever the
//   size (standardization_sampling.h; tests: StandardizationLut.KnotsWithinOneStepOfTheExactTransform_*,
//   StandardizationLut.AtomIsExactWhateverTheSize, BlendedField.MatchesTheExactTransformAtEveryTableSize_*).
//   Uniform tables interpolate across an atom's rise and render another surface.
// - Deviation [Heitz18]: the inverse is indexed by the Gaussian value z itself, over [G(min), G(max)], not by
//   Phi(z) in [0, 1], so its derivative is dG^-1/dz directly (the Jacobian needs no chain rule through Phi),
//   and outside that range G^-1 is exactly the clamped end value, so clamping loses nothing (tests:
//   StandardizationLut.LookupsClampOutsideTheirDomain, StandardizationLut.TailMassIsTheEndRanks).
// - Deviation [Wang20]: derivatives are the slopes of the piecewise-linear interpolants' segments, not of the
//   continuous transform, so values and Jacobians stay consistent (test:
//   StandardizationLut.SlopesAreFiniteDifferencesOfTheInterpolant).
// - Deviation [Yan16], [Wang20]: each texel's element is 2 x 2 sub-elements of sigma_h / 2 at the texel's
//   quarter points, linearized there, not one element linearized at the texel centre. The blended field is
//   piecewise bilinear with kinks on the lines through texel centres, exactly where [Yan16] puts the
//   elements: one slope extrapolated over the whole element (+/- 3 sigma_h = 1.3 texels) overshoots every
//   extreme of the field, so the P-NDF fattened its tails (bumps: 1.2-1.4x the exact mass beyond |s| = 0.4;
//   scratches: 1.6-4x in [0.2, 0.4)) or, with one-sided slopes, lost them to truncation. Sub-elements sit
//   inside the bilinear cells and reach a quarter as far past a kink (test: GlintPndfTailMass.*). Cost: four
//   point queries per texel that passes its box test.
// - Phi^-1 is exact to double precision (Acklam's rational approximation refined by Halley steps on erfc),
//   not a single-precision approximation (tests: StandardNormal.*).
#pragma once

namespace mbk {

// Spatial standard deviation of one texel's position-normal element, in texels ([Yan16]; 1.5 / sqrt(12)): the
// reach of the RMQ leaf intervals (element_normal_bounds.h) and of every element's truncation box.
inline constexpr double kGlintElementSigmaTexels = 0.43301270189221935;
// The P-NDF splits each texel's element into K x K sub-elements of spatial sigma kGlintElementSigmaTexels / K,
// centred at t + (a + 1/2) / K (a = 0..K-1 per axis), each linearized where it sits (glint_pndf.h).
inline constexpr int kGlintSubElementsPerAxis = 2;
// Under histogram blending n = G^-1(z) per channel, and G^-1 bends sharply where an atom's rank range ends: a
// sub-element is evaluated as R x R children (R = kGlintRefinementPerAxis) of spatial sigma / R, each linearized
// where it sits (glint_pndf.h), when over its range of z (its z gradient over kGlintRefinementReachSigmas of its
// spatial sigma per axis) G^-1 leaves its tangent by more than kGlintRefinementSigmas sigma_r AND by more than
// kGlintRefinementBend of the tangent's own spread: a bend, not the gentle curvature of a smooth map's G^-1
// (which refining everywhere cost `gen bumps` 3x for no measurable gain in mass).
inline constexpr int kGlintRefinementPerAxis = 4;
inline constexpr double kGlintRefinementSigmas = 0.5;
inline constexpr double kGlintRefinementBend = 0.5;
inline constexpr double kGlintRefinementReachSigmas = 2.0;
// The aggregated traversal (glint_pndf.h) sums a node in closed form when its bounds are at most this many
// sigma wide in both components.
inline constexpr double kGlintAggregateWidthSigmas = 0.01;
inline constexpr double kGlintSubElementSigmaTexels = kGlintElementSigmaTexels / kGlintSubElementsPerAxis;
// Truncation radii, in standard deviations: spatial (element), normal (intrinsic roughness), pixel footprint.
inline constexpr double kGlintSpatialCutoffSigmas = 3.0;
inline constexpr double kGlintNormalCutoffSigmas = 4.0;
inline constexpr double kGlintFootprintCutoffSigmas = 3.0;
// How far a texel's element reaches from the texel's centre per axis: its farthest sub-element centre
// (1/2 - 1/(2K)) plus that sub-element's spatial cut-off (0.8995 texels for K = 2). The RMQ leaf intervals
// hold the field over this square (element_normal_bounds.h); the P-NDF bounds the half vector's slope field
// over it (glint_pndf.h).
inline constexpr double kGlintElementReachTexels =
    0.5 - 0.5 / kGlintSubElementsPerAxis + kGlintSpatialCutoffSigmas * kGlintSubElementSigmaTexels;

}  // namespace mbk
