// A glint material assembled from its example and assets (see glint_surface.h).
#include "libbake/glint/glint_surface.h"

#include <string>

#include "formats/error.h"

namespace mbk {

GlintBlendMode parse_glint_blend_mode(std::string_view name, const std::string& where) {
  for (const GlintBlendMode m :
       {GlintBlendMode::none, GlintBlendMode::linear, GlintBlendMode::variance, GlintBlendMode::histogram})
    if (name == glint_blend_mode_name(m)) return m;
  throw Error(ExitCode::invalid_input,
              "unknown glint blending '" + std::string(name) + "' (known: none, linear, variance, histogram)", where);
}

const char* glint_blend_mode_name(GlintBlendMode mode) {
  switch (mode) {
    case GlintBlendMode::none:
      return "none";
    case GlintBlendMode::linear:
      return "linear";
    case GlintBlendMode::variance:
      return "variance";
    case GlintBlendMode::histogram:
      return "histogram";
  }
  return "?";
}

GlintSurface::GlintSurface(const NormalMap& example, Asset lut, Asset rmq, const GlintSettings& settings)
    : settings_(settings),
      lut_asset_(std::move(lut)),
      rmq_asset_(std::move(rmq)),
      lut_(read_standardization_lut(lut_asset_)),
      rmq_(RmqTableView::of(rmq_asset_)),
      point_(example, settings.patch, settings.seed, settings.mode, &lut_),
      range_(point_, rmq_),
      pndf_(range_, settings.sigma_r) {}

std::unique_ptr<GlintSurface> GlintSurface::open(const NormalMap& example, Asset lut, Asset rmq,
                                                 const GlintSettings& settings) {
  return std::unique_ptr<GlintSurface>(new GlintSurface(example, std::move(lut), std::move(rmq), settings));
}

}  // namespace mbk
