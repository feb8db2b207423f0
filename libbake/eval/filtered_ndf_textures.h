// The evaluator's view of the filtering assets ([Han07]): `sh` NDF pyramids and `vmf` mixture maps read through
// formats/ (never a baker), looked up trilinearly with the texel-centre and wrapping rules of
// libbake/image/texture_taps.h, at a level of detail `lod` (0 = finest).
//
// SH: coefficients are linear in the NDF, so a lookup is the trilinear blend of stored coefficients; level 0
// (stored as normals) contributes Y_lm of the renormalised bilinear normal of its four taps, one delta, as plain
// normal mapping and `render --reference` shade it (the four taps as separate deltas would add a spread that
// interpolation does not have: on a magnified bumpy map that tripled the error against the reference).
// vMF ([Han07] Sec. 7.6.4.2, Alg. 7.2): the trilinear blend of (alpha, alpha r) (and alpha y) of the lobes of
// every texel the lookup reads - merged by direction, not slot by slot as Alg. 7.2 does (vmf_lobe_merge.h: a slot
// does not hold the same lobe in every texel, and an atom averaged with another lobe shades as a wide lobe) - then
// r = T(alpha r) / T(alpha), kappa = A^-1(|r|) (capped at the asset's kappa_max) and mu = r / |r|. Level 0 (one
// lobe per texel, in varying slots) enters the merge as one delta per read: weight 1 - t, kappa_max, at the
// renormalised interpolated normal, as plain normal mapping shades it. Deviation [Han07]: Alg. 7.2 blends level 0
// per slot like any other level.
// A footprint probe of box width w >= 8 texels reads the texels its box covers at the coarsest level whose texels
// are at most w / 4 (texels of size s, 1/8 to 1/4 of the width on power-of-two maps), each weighted by its overlap
// with the box (texture_taps.h box_taps): the kernel reaches at most s <= w / 4 beyond each edge of the box (a
// trilinear read's tent reaches ~3.5 w in all), and its variance per axis is w^2 / 12 + d (1 - d) s^2 for a box
// edge at fraction d of a texel: (w^2 + 2 s^2) / 12 on average, 12.5% above the box's at s = w / 4, 3% at w / 8.
// A wider kernel reads a neighbour's sparkles into the footprint; a sharper mixture (more lobes) shades them more
// faithfully, so with trilinear kernels more lobes could lose to fewer on a distant sphere (the filtering report's
// distant sphere against 64 x 64-ray references, whose own floor there is 0.0034, 4 spp: metallic_flakes vmf8
// 0.0255 where vmf6 gave 0.0183); with the box read the errors fall with J on every map there (flakes vmf6
// 0.0170, vmf8 0.0132).
// A narrower probe is read as its quarters: 2 x 2 trilinear reads of width w / 2 at +-w / 4 along the texel axes,
// one level finer (the four boxes tile the probe's box; from a probe's level 1 up their kernels' variance is the
// box's, w^2 / 12, below it the quarters' level is clamped at 0). Where a probe's level is below 1 this samples
// the interpolated normal field at four points of the box rather than one, so the deltas' spread is the field's
// spread over the footprint (the reference's NDF there), not nothing; where it is coarser, each read's trilinear
// tent reaches ~2.2 w instead of ~3.5 w. Measured on the filtering report (4 spp against a 16 x 16 reference):
// middle sphere of bumps vmf8 0.0119 -> 0.0075, near sphere of metallic_flakes 0.033 -> 0.010. It costs ~1.5x the
// render time of one read per probe.
#pragma once

#include <span>
#include <vector>

#include "formats/asset.h"
#include "libbake/core/sh_basis.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/eval/uv_footprint.h"

namespace mbk {

class ShNdfTexture {
 public:
  // Error(invalid_input) when the asset is not of kind `sh`.
  static ShNdfTexture from_asset(const Asset& asset);
  int order() const { return basis_.order(); }
  uint32_t width() const { return width_; }  // of the finest level (the normal map's size)
  uint32_t height() const { return height_; }
  const std::vector<double>& window() const { return window_; }
  size_t levels() const { return 1 + levels_.size(); }
  // The part of a lookup that is the finest level: one normal (a delta) of weight 1 - t (t the trilinear weight of
  // the next level); weight 0 where the lookup reads coarser levels only.
  struct FinestDelta {
    double weight = 0.0;
    Vec3 normal = Vec3::UnitZ();
  };
  // g_lm at (uv, lod) into g (size >= (order + 1)^2), and the finest level's delta among them into `finest` if
  // given. NaN uv or lod give NaN coefficients.
  void lookup(const Vec2& uv, double lod, std::span<double> g, FinestDelta* finest = nullptr) const;

 private:
  explicit ShNdfTexture(int order) : basis_(order) {}
  void add_level(size_t level, const Vec2& uv, double weight, std::span<double> g, FinestDelta* finest) const;
  ShBasisEvaluator basis_;
  uint32_t width_ = 0, height_ = 0;
  std::vector<float> normals_;
  std::vector<uint32_t> widths_, heights_;  // of levels 1..
  std::vector<std::vector<float>> levels_;  // levels 1..: [h][w][count]
  std::vector<double> window_;
};

// A probe at least 2 x this many texels wide is read as a box, at the coarsest level whose texels are at most
// 1 / this of its width.
inline constexpr double kVmfBoxTexelsPerWidth = 4.0;

class VmfTexture {
 public:
  // Error(invalid_input) when the asset is not of kind `vmf`.
  static VmfTexture from_asset(const Asset& asset);
  int lobes() const { return lobes_; }
  int feature_count() const { return features_; }
  uint32_t width() const { return widths_.empty() ? 0 : widths_[0]; }  // of the finest level (the map's size)
  uint32_t height() const { return heights_.empty() ? 0 : heights_[0]; }
  size_t levels() const { return levels_.size(); }
  // Alg. 7.2 lines 5-10: the lobes at (uv, lod), one trilinear read: J, plus one more below LOD 1, where level 0's
  // delta joins the merge (see above); features (when non-null) receives one F-vector y_j per returned lobe
  // (already divided by the interpolated alpha; 0 for an empty slot). NaN uv or lod give J empty lobes.
  std::vector<VmfLobeShape> lookup(const Vec2& uv, double lod, std::vector<double>* features = nullptr) const;
  // The same over an anisotropic footprint: every probe read as its box or its quarters (above), their lobes
  // merged, so still J lobes, + 1 where a read reaches level 0 (a probe below LOD 2). Any non-finite probe gives
  // J empty lobes.
  std::vector<VmfLobeShape> lookup(const FootprintProbes& probes, std::vector<double>* features = nullptr) const;

 private:
  // The level a probe of box width `width` (texels) reads as a box, or 0 where it is read as its quarters.
  size_t box_level(double width) const;

  int lobes_ = 0, features_ = 0;
  double kappa_max_ = 0.0;
  std::vector<uint32_t> widths_, heights_;
  std::vector<std::vector<float>> levels_, feature_levels_;
};

}  // namespace mbk
