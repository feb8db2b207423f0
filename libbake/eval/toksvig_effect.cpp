// The Toksvig shader (see toksvig_effect.h).
#include "libbake/eval/toksvig_effect.h"

#include <algorithm>
#include <cmath>

#include "libbake/eval/filtered_ndf_shading.h"
#include "libbake/eval/mip_effect.h"

namespace mbk {
namespace {

class ToksvigShader : public MaterialShader {
 public:
  explicit ToksvigShader(std::shared_ptr<const NormalPyramid> pyramid) : pyramid_(std::move(pyramid)) {}

  Vec3 radiance(const ShadingContext& c, const Brdf& brdf) const override {
    const NormalMap& finest = pyramid_->levels[0];
    const FootprintProbes probes = footprint_probes(c.uv, c.footprint, finest.width, finest.height);
    Vec3 m = Vec3::Zero();  // the footprint's mean normal: the mean of its probes' means
    for (const FootprintProbe& p : probes) {
      m += sample_pyramid(*pyramid_, p.uv, p.lod);
      if (p.lod < 1.0) {
        // The level-0 part (weight 1 - lod) is the bilinear blend of four unit normals, shorter than 1 between
        // unequal taps; plain normal mapping and the reference shade it renormalised, so do we (no widening from
        // interpolation alone; test: FilteredNdfEffects.MagnifiedBumpyMapMatchesPlainNormalMapping).
        const Vec3 m0 = sample_bilinear(finest, p.uv);
        const double len0 = m0.norm();
        if (len0 > 1e-6) m += (1.0 - std::max(0.0, p.lod)) * (m0 / len0 - m0);
      }
    }
    m /= probes.size();
    const double len = m.norm();
    // As material_normals.cpp: a mean shorter than 1e-6 has lost its direction (and its lobe is flat).
    const Vec3 n = len > 1e-6 ? Vec3(m / len) : Vec3::UnitZ();
    Brdf widened = brdf;
    widened.lobe.alpha = clamp_filtered_alpha(brdf.lobe.alpha, toksvig_beckmann_alpha(brdf.lobe.alpha, len));
    return shade(*c.lighting, widened, {c.position, c.frame.N, c.frame.to_world(n).normalized(), c.to_viewer});
  }

 private:
  std::shared_ptr<const NormalPyramid> pyramid_;
};

}  // namespace

ShaderPtr toksvig_effect_shader(const EffectShaderRequest& request) {
  if (request.mode == EvalMode::reference) return request.base;
  const std::filesystem::path& file = request.assets.at(0);
  return std::make_shared<ToksvigShader>(
      request.cache.get<NormalPyramid>("mip asset|" + file.string(), [&] { return load_mip_asset(file); }));
}

}  // namespace mbk
