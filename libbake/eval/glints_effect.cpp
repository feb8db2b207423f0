// The glint shaders (see glints_effect.h).
#include "libbake/eval/glints_effect.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <utility>

#include "formats/asset.h"
#include "formats/error.h"
#include "libbake/core/progress.h"
#include "libbake/glint/glint_surface.h"
#include "libbake/glint/glint_surface_mapping.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/eval/mip_effect.h"

namespace mbk {
namespace {

// D(s) at a shading point, s = (h_x, h_y) in the tangent frame, for a pixel over which s sweeps with standard
// deviation `spread` (the reference traces rays over the pixel instead, and ignores it).
using GlintDistribution = std::function<double(const Vec2& s, double spread)>;
using DistributionAt = std::function<GlintDistribution(const ShadingContext& c)>;

// The standard deviation of s = (h . T, h . B) over the pixel, for the light in direction l at `distance`:
// h = (l + v) / |l + v| moves by dh = (I - h h^T)(dl + dv) / |l + v| per pixel step, with
// dl = -(dp - l (l . dp)) / distance (0 for a directional light) and dv from the footprint; a box pixel spreads
// each step's ds uniformly over one step, variance |ds|^2 / 12 per step, split evenly between the two components
// of s (glint_pndf.h: "Directional spread").
double half_vector_spread(const ShadingContext& c, const Vec3& l, double distance) {
  const Vec3 sum = l + c.to_viewer;
  const double length = sum.norm();
  if (!(length > 1e-12)) return 0.0;
  const Vec3 h = sum / length;
  double variance = 0.0;
  for (const auto& [dp, dv] :
       {std::pair{c.footprint.dp_dx, c.footprint.dview_dx}, std::pair{c.footprint.dp_dy, c.footprint.dview_dy}}) {
    const Vec3 dl = std::isfinite(distance) ? Vec3(-(dp - l * l.dot(dp)) / distance) : Vec3::Zero();
    const Vec3 dh = ((dl + dv) - h * h.dot(dl + dv)) / length;
    variance += (std::pow(dh.dot(c.frame.T), 2) + std::pow(dh.dot(c.frame.B), 2)) / 12.0;
  }
  const double spread = std::sqrt(variance / 2.0);
  return std::isfinite(spread) ? spread : 0.0;  // a grazing ray's infinite step: no spread rather than none at all
}

class GlintShader : public MaterialShader {
 public:
  explicit GlintShader(DistributionAt distribution) : at_(std::move(distribution)) {}

  Vec3 radiance(const ShadingContext& c, const Brdf& brdf) const override {
    const Vec3& n = c.frame.N;
    const Vec3& v = c.to_viewer;
    SceneLighting distant = *c.lighting;  // the distant lighting alone, with the base roughness
    distant.points.clear();
    distant.directionals.clear();
    Vec3 out = shade(distant, brdf, {c.position, n, n, v});
    if (!(n.dot(v) > 0.0)) return out;
    const GlintDistribution d = at_(c);
    for_each_direct_light(*c.lighting, c.position, n, [&](const Vec3& l, const Vec3& e, double distance) {
      const double spread = half_vector_spread(c, l, distance);
      const Vec3 spec = evaluate_specular(
          brdf, n, l, v, [&](const Vec3& h) { return d(Vec2(h.dot(c.frame.T), h.dot(c.frame.B)), spread); });
      out += (brdf.albedo / std::numbers::pi + spec).cwiseProduct(e) * n.dot(l);
    });
    return out;
  }

 private:
  DistributionAt at_;
};

GlintSettings settings_of(const EffectUse& use, const std::string& where) {
  GlintSettings s;
  s.mode = parse_glint_blend_mode(use.options.at("blending").get<std::string>(), where);
  s.sigma_r = use.options.at("sigma_r");
  s.patch = use.options.at("patch");
  s.seed = use.options.at("seed");
  return s;
}

}  // namespace

ShaderPtr glints_effect_shader(const EffectShaderRequest& request) {
  const std::string where = "materials." + request.material.name + ": glints";
  if (!request.material.normal_map)
    throw Error(ExitCode::invalid_input, "the glints effect needs the material's normal map", where);
  const NormalMapRef& ref = *request.material.normal_map;
  const GlintSettings settings = settings_of(request.use, where);

  if (request.mode == EvalMode::reference) {
    const auto example = request.cache.get<LoadedNormalMap>(
        "glint example|" + ref.path.string(), [&] { return load_normal_map(ref.path, ref.load_options()); });
    const uint32_t W = example->map.width, H = example->map.height;
    // No assets: the exact example, standardized here when the blend needs it, by the baker's own function at the
    // material's lut_size: the very knots the effect's asset holds (test: GlintsEffect.ReferenceUsesTheAssetsKnots),
    // so effect and reference render one microstructure.
    struct Reference {
      std::shared_ptr<const LoadedNormalMap> example;
      StandardizationLut lut;
      std::unique_ptr<GlintPointQuery> point;
    };
    auto r = std::make_shared<Reference>();
    r->example = example;
    if (settings.mode == GlintBlendMode::histogram)
      r->lut = bake_standardization_lut(example->map, request.use.options.at("lut_size"), Progress::silent()).tables;
    r->point = std::make_unique<GlintPointQuery>(example->map, settings.patch, settings.seed, settings.mode, &r->lut);
    const double sigma_r = settings.sigma_r;
    return std::make_shared<GlintShader>([r, sigma_r, W, H](const ShadingContext& c) {
      const Vec2 u = glint_target_point(c.uv, W, H);
      return GlintDistribution([r, sigma_r, u](const Vec2& s, double) { return point_ndf(*r->point, u, sigma_r, s); });
    });
  }

  // The example is level 0 of the map's baked `mip` asset (the decoded map itself, as f32), so no source is read.
  struct Filtered {
    std::shared_ptr<const NormalPyramid> example;
    std::unique_ptr<GlintSurface> surface;
  };
  auto f = std::make_shared<Filtered>();
  const std::filesystem::path& mip = request.assets.at(2);
  f->example = request.cache.get<NormalPyramid>("mip asset|" + mip.string(), [&] { return load_mip_asset(mip); });
  const NormalMap& example = f->example->levels.at(0);
  const uint32_t W = example.width, H = example.height;
  f->surface =
      GlintSurface::open(example, Asset::open(request.assets.at(0)), Asset::open(request.assets.at(1)), settings);
  return std::make_shared<GlintShader>([f, W, H](const ShadingContext& c) {
    const GlintFootprint fp = glint_pixel_footprint(c.uv, c.footprint.duv_dx, c.footprint.duv_dy, W, H);
    if (!std::isfinite(fp.sigma)) return GlintDistribution([](const Vec2&, double) { return 0.0; });  // grazing
    return GlintDistribution([f, fp](const Vec2& s, double spread) {
      GlintFootprint swept = fp;
      swept.normal_spread = spread;
      return f->surface->ndf(swept, s, false);
    });
  });
}

}  // namespace mbk
