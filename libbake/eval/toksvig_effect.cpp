// The Toksvig shader (see toksvig_effect.h).
#include "libbake/eval/toksvig_effect.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "libbake/eval/filtered_ndf_shading.h"
#include "libbake/eval/lobe_specular.h"
#include "libbake/eval/mip_effect.h"
#include "libbake/eval/scene_lighting.h"

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
    const double widened = clamp_filtered_alpha(brdf.lobe.alpha, toksvig_beckmann_alpha(brdf.lobe.alpha, len));
    // The spread as a vMF lobe: variance 1 / kappa per axis is Toksvig's sigma^2 (the same alpha' either way).
    const double kappa = 1.0 / toksvig_variance(len);
    const Vec3& v = c.to_viewer;
    const Vec3 mu = c.frame.to_world(n).normalized();
    const Vec3 bent = facing_viewer(mu, v);
    const std::array<SpecularLobe, 1> lobe{{{1.0, mu, kappa, widened}}};
    Vec3 out = Vec3::Zero();
    for_each_direct_light(*c.lighting, c.position, c.frame.N, [&](const Vec3& l, const Vec3& e, double) {
      const Vec3 diffuse = brdf.albedo * (std::max(0.0, bent.dot(l)) / std::numbers::pi);
      out += (diffuse + lobes_specular(brdf, lobe, l, v)).cwiseProduct(e);
    });
    return out + shade_distant(*c.lighting, brdf, bent, v, widened);
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
