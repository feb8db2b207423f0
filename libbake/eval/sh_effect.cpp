// The SH-NDF shader (see sh_effect.h).
#include "libbake/eval/sh_effect.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "formats/asset.h"
#include "formats/error.h"
#include "libbake/core/gauss_legendre.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/eval/filtered_ndf_shading.h"
#include "libbake/eval/filtered_ndf_textures.h"
#include "libbake/eval/lobe_specular.h"
#include "libbake/eval/sh_lobe_tail.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

// Tangent-space nodes of a product rule exact for polynomials of degree <= 4 on the sphere: 3 Gauss-Legendre
// nodes in z = cos(theta) (exact to degree 5) times 5 equally spaced azimuths (exact for trigonometric
// degree 4), with the bands l <= 2 of the SH basis at each node.
struct SphereRule {
  std::vector<Vec3> directions;
  std::vector<double> weights;
  std::vector<std::array<double, 9>> basis;
};

SphereRule degree4_rule() {
  SphereRule rule;
  const ShBasisEvaluator basis(2);
  for (const QuadratureNode& z : composite_gauss_legendre(-1.0, 1.0, 1, 3))
    for (int k = 0; k < 5; ++k) {
      const double phi = 2 * kPi * k / 5, s = std::sqrt(std::max(0.0, 1.0 - z.x * z.x));
      const Vec3 d(s * std::cos(phi), s * std::sin(phi), z.x);
      rule.directions.push_back(d);
      rule.weights.push_back(z.w * 2 * kPi / 5);
      std::array<double, 9> y{};
      basis.evaluate(d, y);
      rule.basis.push_back(y);
    }
  return rule;
}

class ShNdfShader : public MaterialShader {
 public:
  ShNdfShader(std::shared_ptr<const ShNdfTexture> texture, const Material& material)
      : texture_(std::move(texture)),
        basis_(texture_->order()),
        rhat_diffuse_(lambertian_rhat(texture_->order())),
        rhat_specular_(microfacet_rhat(Brdf::of(material).lobe, texture_->order())),
        unwindowed_(size_t(texture_->order()) + 1, 1.0),
        tail_(Brdf::of(material).lobe, texture_->order()),
        lobe_bands_(Brdf::of(material).lobe, -1),
        rule_(degree4_rule()) {}

  Vec3 radiance(const ShadingContext& c, const Brdf& brdf) const override {
    const int order = texture_->order();
    // The footprint's NDF: SH coefficients are linear in it, so the mean of its probes' coefficients.
    std::vector<double> g(size_t(basis_.count()), 0.0), probe_g(g.size());
    const FootprintProbes probes = footprint_probes(c.uv, c.footprint, texture_->width(), texture_->height());
    for (const FootprintProbe& p : probes) {
      texture_->lookup(p.uv, p.lod, probe_g);
      for (size_t k = 0; k < g.size(); ++k) g[k] += probe_g[k] / probes.size();
    }
    const SurfaceFrame& f = c.frame;
    const auto to_tangent = [&](const Vec3& w) { return Vec3(w.dot(f.T), w.dot(f.B), w.dot(f.N)); };
    const std::span<const double> window(texture_->window());

    // The mean normal from the first band: g_1m = sqrt(3 / (4 pi)) E[(y, z, x)].
    const double c1 = std::sqrt(3.0 / (4.0 * kPi));
    const Vec3 mean =
        order >= 1 ? Vec3(Vec3(g[size_t(sh_index(1, 1))], g[size_t(sh_index(1, -1))], g[size_t(sh_index(1, 0))]) / c1)
                   : Vec3(Vec3::Zero());
    const double len = mean.norm();
    const Vec3 n = facing_viewer(f.to_world(len > 1e-6 ? Vec3(mean / len) : Vec3::UnitZ()).normalized(), c.to_viewer);

    // The spread of the NDF as one lobe (Toksvig's variance of |mean|): the masking-shadowing of the filtered
    // lobe and the distant specular use it (D itself comes from the full SH expansion).
    Brdf spread = brdf;
    spread.lobe.alpha =
        clamp_filtered_alpha(brdf.lobe.alpha, toksvig_beckmann_alpha(brdf.lobe.alpha, std::min(1.0, len)));

    // D: the stored bands, unwindowed, plus the bands beyond the order completed from the vMF lobe of the mean
    // normal (sh_lobe_tail.h), so a sharp NDF under a narrow lobe neither rings nor smears.
    const double kappa = vmf_kappa_from_mean_length(std::min(1.0, len), INFINITY);
    const Vec3 mu = len > 1e-6 ? Vec3(mean / len) : Vec3::UnitZ();
    // The vMF lobe of the mean (lobe_specular.h): where it is wide, the product below misses how 1 / (n . v), G2
    // and the bending of normals behind the view horizon vary over the NDF, and lobe_corrected_specular applies the
    // lobe's integral to it.
    const SpecularLobe lobe{1.0, f.to_world(mu).normalized(), kappa, spread.lobe.alpha};
    Vec3 out = Vec3::Zero();
    for_each_direct_light(*c.lighting, c.position, f.N, [&](const Vec3& l, const Vec3& e, double) {
      const double diffuse = std::max(0.0, sh_filtered_brdf(basis_, g, window, rhat_diffuse_, to_tangent(l)));
      Vec3 specular =
          evaluate_specular(spread, n, l, c.to_viewer,
                            [&](const Vec3& h) {
                              const Vec3 h_tangent = to_tangent(h);
                              return std::max(0.0, sh_filtered_brdf(basis_, g, unwindowed_, rhat_specular_, h_tangent) +
                                                       tail_.value(h_tangent.dot(mu), kappa));
                            }) *
          n.dot(l);
      if (!lobe_specular_is_product(lobe, l, c.to_viewer)) {
        // The lobe's D through the same expansion: every band of the vMF lobe (the tail from band 0).
        const Vec3 lobe_product =
            evaluate_specular(spread, n, l, c.to_viewer,
                              [&](const Vec3& h) { return lobe_bands_.value(to_tangent(h).dot(mu), kappa); }) *
            n.dot(l);
        specular = lobe_corrected_specular(specular, lobe_product,
                                           lobes_specular_integrated(brdf, std::span(&lobe, 1), l, c.to_viewer));
      }
      out += (brdf.albedo * (diffuse / kPi) + specular).cwiseProduct(e);
    });
    if (c.lighting->has_distant) {
      // integral g_2(n) E(n) dn over the sphere, g_2 = sum_{l <= 2} window_l g_lm Y_lm.
      Vec3 irradiance = Vec3::Zero();
      for (size_t q = 0; q < rule_.directions.size(); ++q) {
        double density = 0.0;
        for (int k = 0; k < std::min(9, basis_.count()); ++k)
          density += window[size_t(k < 1 ? 0 : k < 4 ? 1 : 2)] * g[size_t(k)] * rule_.basis[q][size_t(k)];
        irradiance += rule_.weights[q] * density * sh_irradiance(c.lighting->distant, f.to_world(rule_.directions[q]));
      }
      out += brdf.albedo.cwiseProduct(irradiance.cwiseMax(0.0)) / kPi;
      out += distant_specular(*c.lighting, brdf.f0, n, c.to_viewer, spread.lobe.alpha);
    }
    return out;
  }

 private:
  std::shared_ptr<const ShNdfTexture> texture_;
  ShBasisEvaluator basis_;
  std::vector<double> rhat_diffuse_, rhat_specular_;
  std::vector<double> unwindowed_;  // the specular's stored bands are completed, not windowed
  ShLobeTail tail_;
  ShLobeTail lobe_bands_;  // every band of the vMF lobe of the mean (a tail from band 0)
  SphereRule rule_;
};

}  // namespace

ShaderPtr sh_effect_shader(const EffectShaderRequest& request) {
  if (request.mode == EvalMode::reference) return request.base;
  const std::filesystem::path& file = request.assets.at(0);
  const auto texture = request.cache.get<ShNdfTexture>("sh asset|" + file.string(),
                                                       [&] { return ShNdfTexture::from_asset(Asset::open(file)); });
  return std::make_shared<ShNdfShader>(texture, request.material);
}

}  // namespace mbk
