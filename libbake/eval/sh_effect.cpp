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

// The mean normal of an NDF from its first band, g_1m = sqrt(3 / (4 pi)) E[(y, z, x)]: unit direction (+z where
// the mean vanishes) and length |E[n]| in [0, 1].
struct MeanNormal {
  Vec3 direction = Vec3::UnitZ();
  double length = 0.0;
};

MeanNormal mean_normal(std::span<const double> g) {
  if (g.size() < 4) return {};
  const double c1 = std::sqrt(3.0 / (4.0 * kPi));
  const Vec3 mean = Vec3(g[size_t(sh_index(1, 1))], g[size_t(sh_index(1, -1))], g[size_t(sh_index(1, 0))]) / c1;
  const double len = mean.norm();
  return len > 1e-6 ? MeanNormal{mean / len, std::min(1.0, len)} : MeanNormal{};
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
    // The footprint's NDF: SH coefficients are linear in it, so the mean of its probes' coefficients. The probes'
    // finest-level parts are single normals (deltas), also kept apart: the specular shades them exactly as the
    // reference shades a normal (lobe_specular.h's product at that normal, the material's own alpha), and only the
    // rest, g_rest = g - sum_d w_d Y(n_d) of weight 1 - sum_d w_d, through the SH product (sh_specular). So a long
    // footprint that reads a few finest-level normals keeps their highlight instead of spreading it through one
    // widened lobe whose masking (at a grazing view) darkens it.
    std::vector<double> g(size_t(basis_.count()), 0.0), probe_g(g.size()), rest(g.size(), 0.0), y(g.size());
    double rest_weight = 1.0;
    std::vector<SpecularLobe> deltas;  // world-space normals, kappa = inf
    const SurfaceFrame& f = c.frame;
    const FootprintProbes probes = footprint_probes(c.uv, c.footprint, texture_->width(), texture_->height());
    for (const FootprintProbe& p : probes) {
      ShNdfTexture::FinestDelta delta;
      texture_->lookup(p.uv, p.lod, probe_g, &delta);
      const double w = delta.weight / probes.size();
      if (w > 0.0) basis_.evaluate(delta.normal, y);
      for (size_t k = 0; k < g.size(); ++k) {
        g[k] += probe_g[k] / probes.size();
        rest[k] += probe_g[k] / probes.size() - (w > 0.0 ? w * y[k] : 0.0);
      }
      if (w > 0.0) {
        deltas.push_back({w, f.to_world(delta.normal).normalized(), INFINITY, brdf.lobe.alpha});
        rest_weight -= w;
      }
    }
    const bool has_rest = rest_weight > 1e-9;
    if (has_rest)
      for (double& r : rest) r /= rest_weight;
    const std::span<const double> window(texture_->window());

    // The footprint's mean normal and the spread of its NDF as one lobe (Toksvig's variance of |mean|): the
    // distant specular uses them.
    const MeanNormal mean = mean_normal(g);
    const Vec3 n = facing_viewer(f.to_world(mean.direction).normalized(), c.to_viewer);
    const double spread_alpha =
        clamp_filtered_alpha(brdf.lobe.alpha, toksvig_beckmann_alpha(brdf.lobe.alpha, mean.length));

    Vec3 out = Vec3::Zero();
    for_each_direct_light(*c.lighting, c.position, f.N, [&](const Vec3& l, const Vec3& e, double) {
      const double diffuse = std::max(0.0, sh_filtered_brdf(basis_, g, window, rhat_diffuse_, f.to_tangent(l)));
      Vec3 specular = lobes_specular(brdf, deltas, l, c.to_viewer);
      if (has_rest) specular += rest_weight * sh_specular(rest, f, brdf, l, c.to_viewer);
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
      out += distant_specular(*c.lighting, brdf.f0, n, c.to_viewer, spread_alpha);
    }
    return out;
  }

 private:
  // The specular of an NDF known by its SH coefficients g (no deltas among them needed), under light l:
  // D = the stored bands, unwindowed, plus the bands beyond the order completed from the vMF lobe of the mean
  // normal (sh_lobe_tail.h), so a sharp NDF under a narrow lobe neither rings nor smears; F, G2 (at the lobe
  // widened by Toksvig's variance of |mean|) and the denominators at the mean normal ([Han07] Eq. 7.12). Where the
  // vMF lobe of the mean is wide (lobe_specular.h), that product misses how 1 / (n . v), G2 and the bending of
  // normals behind the view horizon vary over the NDF, and lobe_corrected_specular applies the lobe's integral.
  Vec3 sh_specular(std::span<const double> g, const SurfaceFrame& f, const Brdf& brdf, const Vec3& l,
                   const Vec3& v) const {
    const MeanNormal mean = mean_normal(g);
    const Vec3 n = facing_viewer(f.to_world(mean.direction).normalized(), v);
    Brdf spread = brdf;
    spread.lobe.alpha = clamp_filtered_alpha(brdf.lobe.alpha, toksvig_beckmann_alpha(brdf.lobe.alpha, mean.length));
    const double kappa = vmf_kappa_from_mean_length(mean.length, INFINITY);
    const Vec3& mu = mean.direction;
    Vec3 specular =
        evaluate_specular(spread, n, l, v,
                          [&](const Vec3& h) {
                            const Vec3 h_tangent = f.to_tangent(h);
                            return std::max(0.0, sh_filtered_brdf(basis_, g, unwindowed_, rhat_specular_, h_tangent) +
                                                     tail_.value(h_tangent.dot(mu), kappa));
                          }) *
        n.dot(l);
    const SpecularLobe lobe{1.0, f.to_world(mu).normalized(), kappa, spread.lobe.alpha};
    if (!lobe_specular_is_product(lobe, l, v)) {
      // The lobe's D through the same expansion: every band of the vMF lobe (the tail from band 0).
      const Vec3 lobe_product =
          evaluate_specular(spread, n, l, v,
                            [&](const Vec3& h) { return lobe_bands_.value(f.to_tangent(h).dot(mu), kappa); }) *
          n.dot(l);
      specular =
          lobe_corrected_specular(specular, lobe_product, lobes_specular_integrated(brdf, std::span(&lobe, 1), l, v));
    }
    return specular;
  }

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
