// A glint material as the evaluator shades it ([Wang20]): the example normal map, its two baked assets (`lut`
// and `rmq`, read through formats/ only) and the settings of the infinite microstructure, assembled into the
// point query, the range query and the P-NDF. The evaluator's shader evaluates pndf() over the pixel's footprint
// at the half vector's normal components, with the half vector's slope field over it (glint_surface_mapping.h),
// by the aggregated traversal.
#pragma once

#include <cstdint>
#include <memory>
#include <string_view>

#include "formats/asset.h"
#include "formats/rmq_query.h"
#include "formats/standardization_lut.h"
#include "libbake/glint/glint_pndf.h"

namespace mbk {

struct GlintSettings {
  GlintBlendMode mode = GlintBlendMode::histogram;
  double sigma_r = 0.01;  // intrinsic roughness, normal units
  uint32_t patch = 64;    // example patch side P, texels (even; target patches are P / 2)
  uint32_t seed = 1;      // patch placement hash seed
};

// "none", "linear", "variance", "histogram"; Error(invalid_input) naming `where` otherwise.
GlintBlendMode parse_glint_blend_mode(std::string_view name, const std::string& where);
const char* glint_blend_mode_name(GlintBlendMode mode);

class GlintSurface {
 public:
  // `example` must outlive the surface. Throws Error(invalid_input) naming the asset when an asset is not a
  // usable lut / rmq asset or describes an example of another size, and for bad settings (odd or out-of-range
  // patch, sigma_r not > 0).
  static std::unique_ptr<GlintSurface> open(const NormalMap& example, Asset lut, Asset rmq,
                                            const GlintSettings& settings);

  const GlintSettings& settings() const { return settings_; }
  const GlintPndf& pndf() const { return pndf_; }

  GlintSurface(const GlintSurface&) = delete;
  GlintSurface& operator=(const GlintSurface&) = delete;

 private:
  GlintSurface(const NormalMap& example, Asset lut, Asset rmq, const GlintSettings& settings);

  GlintSettings settings_;
  Asset lut_asset_, rmq_asset_;
  StandardizationLut lut_;
  RmqTableView rmq_;
  GlintPointQuery point_;
  GlintRangeQuery range_;
  GlintPndf pndf_;
};

}  // namespace mbk
