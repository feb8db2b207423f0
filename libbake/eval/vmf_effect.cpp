// The vMF-mixture shader (see vmf_effect.h).
#include "libbake/eval/vmf_effect.h"

#include <algorithm>
#include <array>
#include <numbers>

#include "formats/asset.h"
#include "libbake/eval/filtered_ndf_shading.h"
#include "libbake/eval/filtered_ndf_textures.h"
#include "libbake/eval/lobe_specular.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

class VmfShader : public MaterialShader {
 public:
  explicit VmfShader(std::shared_ptr<const VmfTexture> texture)
      : texture_(std::move(texture)), rhat_diffuse_(lambertian_rhat(kVmfDiffuseOrder)), basis_(2) {}

  Vec3 radiance(const ShadingContext& c, const Brdf& brdf) const override {
    const SurfaceFrame& f = c.frame;
    const Vec3& v = c.to_viewer;
    // The lobes in world space, each with its widened roughness (Eq. 7.21).
    std::vector<VmfLobeShape> lobes;
    std::vector<SpecularLobe> specular_lobes;  // the same, unbent, for lobe_specular.h (which bends its own points)
    std::vector<Brdf> widened;
    std::vector<std::vector<double>> filtered;  // rhat_l Lambda_l(kappa_j), once per lobe (Eqs. 7.14, 7.23)
    const FootprintProbes probes = footprint_probes(c.uv, c.footprint, texture_->width(), texture_->height());
    for (VmfLobeShape lobe : texture_->lookup(probes)) {
      if (!(lobe.alpha > 0.0)) continue;
      const Vec3 mu = f.to_world(lobe.mu).normalized();
      lobe.mu = facing_viewer(mu, v);
      Brdf b = brdf;
      b.lobe.alpha = clamp_filtered_alpha(brdf.lobe.alpha, vmf_filtered_beckmann_alpha(brdf.lobe.alpha, lobe.kappa));
      lobes.push_back(lobe);
      widened.push_back(b);
      specular_lobes.push_back({lobe.alpha, mu, lobe.kappa, b.lobe.alpha});
      filtered.push_back(vmf_filtered_rhat(rhat_diffuse_, lobe.kappa));
    }

    Vec3 out = Vec3::Zero();
    for_each_direct_light(*c.lighting, c.position, f.N, [&](const Vec3& l, const Vec3& e, double) {
      const double diffuse = std::max(0.0, vmf_filtered_brdf(lobes, filtered, l));  // Eq. (7.14)
      const Vec3 specular = lobes_specular(brdf, specular_lobes, l, v);
      out += (brdf.albedo * (diffuse / kPi) + specular).cwiseProduct(e);
    });
    if (c.lighting->has_distant) {
      std::array<std::array<double, kShCount>, 3> light{};  // per channel
      for (int k = 0; k < kShCount; ++k)
        for (int ch = 0; ch < 3; ++ch) light[size_t(ch)][size_t(k)] = c.lighting->distant[size_t(k)][ch];
      std::array<double, kShCount> y_mu{};
      for (size_t j = 0; j < lobes.size(); ++j) {
        basis_.evaluate(lobes[j].mu, y_mu);
        Vec3 irradiance;
        for (int ch = 0; ch < 3; ++ch)  // Eq. (7.23)
          irradiance[ch] = std::max(0.0, vmf_sh_lighting(light[size_t(ch)], filtered[j], y_mu));
        out += lobes[j].alpha * (brdf.albedo.cwiseProduct(irradiance) / kPi +
                                 distant_specular(*c.lighting, brdf.f0, lobes[j].mu, v, widened[j].lobe.alpha));
      }
    }
    return out;
  }

 private:
  std::shared_ptr<const VmfTexture> texture_;
  std::vector<double> rhat_diffuse_;
  ShBasisEvaluator basis_;  // order 2, that of the renderer's distant lighting (kShCount = 9 coefficients)
};

}  // namespace

ShaderPtr vmf_effect_shader(const EffectShaderRequest& request) {
  if (request.mode == EvalMode::reference) return request.base;
  const std::filesystem::path& file = request.assets.at(0);
  return std::make_shared<VmfShader>(request.cache.get<VmfTexture>(
      "vmf asset|" + file.string(), [&] { return VmfTexture::from_asset(Asset::open(file)); }));
}

}  // namespace mbk
