// The glint shaders (see glints_effect.h).
#include "libbake/eval/glints_effect.h"

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include "formats/asset.h"
#include "formats/error.h"
#include "libbake/core/progress.h"
#include "libbake/eval/mip_effect.h"
#include "libbake/eval/uv_footprint.h"
#include "libbake/glint/glint_surface.h"
#include "libbake/glint/glint_surface_mapping.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/pixel_sweep.h"

namespace mbk {
namespace {

// D(s) at a shading point, s = (h_x, h_y) in the tangent frame, for a pixel over which s moves by the columns of
// `steps` per pixel step (the reference traces rays over the pixel instead, and ignores it).
using GlintDistribution = std::function<double(const Vec2& s, const Mat2& steps)>;
using DistributionAt = std::function<GlintDistribution(const ShadingContext& c)>;

// ds per pixel step, s = (h . T, h . B), for the light in direction l at `distance`: h = (l + v) / |l + v| moves
// by dh = (I - h h^T)(dl + dv) / |l + v| per step, with dl = -(dp - l (l . dp)) / distance (0 for a directional
// light) and dv from the footprint, and on a curved surface the frame turns with the normal: to first order
// dT = -N (T . dN), dB = -N (B . dN), adding -(h . N)(T . dN, B . dN). The P-NDF turns them into the half
// vector's slope field over the footprint (glint_surface_mapping.h, glint_pndf.h). At grazing angles the two steps
// differ by an order of magnitude.
Mat2 half_vector_steps(const ShadingContext& c, const Vec3& l, double distance) {
  const Vec3 sum = l + c.to_viewer;
  const double length = sum.norm();
  if (!(length > 1e-12)) return Mat2::Zero();
  const Vec3 h = sum / length;
  Mat2 steps;
  int k = 0;
  const UvFootprint& f = c.footprint;
  for (const auto& [dp, dv, dn] :
       {std::tuple{f.dp_dx, f.dview_dx, f.dnormal_dx}, std::tuple{f.dp_dy, f.dview_dy, f.dnormal_dy}}) {
    const Vec3 dl = std::isfinite(distance) ? Vec3(-(dp - l * l.dot(dp)) / distance) : Vec3::Zero();
    const Vec3 dh = ((dl + dv) - h * h.dot(dl + dv)) / length;
    const double turn = -h.dot(c.frame.N);
    steps.col(k++) = Vec2(dh.dot(c.frame.T) + turn * c.frame.T.dot(dn), dh.dot(c.frame.B) + turn * c.frame.B.dot(dn));
  }
  // A grazing ray's infinite step: no sweep rather than none at all.
  return steps.allFinite() ? steps : Mat2::Zero();
}

// D_P over one cell of a pixel at uv (the whole pixel when it is one cell), whose half vector at its centre is s and
// moves by the columns of `steps` per cell step: its anisotropic footprint as probes along its major axis
// (glint_surface_mapping.h), equally weighted, each seeing the half vector's slope field K (its own s moved by K
// along its offset). 0 for a grazing footprint.
double cell_pndf(const GlintPndf& pndf, const Vec2& uv, const UvFootprint& cell, const Vec2& s, const Mat2& steps,
                 uint32_t W, uint32_t H) {
  const FootprintProbes probes = footprint_probes(uv, cell, W, H);
  const double probe_sigma = glint_probe_footprint(uv, probes.begin()->width, W, H).sigma;
  if (!std::isfinite(probe_sigma)) return 0.0;  // grazing
  const Vec2 centre = glint_target_point(uv, W, H);
  const Mat2 slope = glint_half_vector_slope(steps, cell.duv_dx, cell.duv_dy, probe_sigma, W, H);
  double sum = 0.0;
  for (const FootprintProbe& p : probes) {
    GlintFootprint footprint = glint_probe_footprint(p.uv, p.width, W, H);
    footprint.slope = slope;
    sum += pndf.evaluate(footprint, s + slope * (footprint.center - centre), nullptr, true);
  }
  return sum / double(probes.size());
}

class GlintShader : public MaterialShader {
 public:
  // `swept`: the distribution reads the half vector's sweep over the pixel (the filtered effect, not the reference).
  GlintShader(DistributionAt distribution, bool swept) : at_(std::move(distribution)), swept_(swept) {}
  bool uses_normal_steps() const override { return swept_; }

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
      const Mat2 steps = half_vector_steps(c, l, distance);
      const Vec3 spec = evaluate_specular(
          brdf, n, l, v, [&](const Vec3& h) { return d(Vec2(h.dot(c.frame.T), h.dot(c.frame.B)), steps); });
      out += (brdf.albedo / std::numbers::pi + spec).cwiseProduct(e) * n.dot(l);
    });
    return out;
  }

 private:
  DistributionAt at_;
  bool swept_;
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
    return std::make_shared<GlintShader>(
        [r, sigma_r, W, H](const ShadingContext& c) {
          const Vec2 u = glint_target_point(c.uv, W, H);
          return GlintDistribution(
              [r, sigma_r, u](const Vec2& s, const Mat2&) { return point_ndf(*r->point, u, sigma_r, s); });
        },
        false);
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
  return std::make_shared<GlintShader>(
      [f, W, H](const ShadingContext& c) {
        return GlintDistribution([f, uv = c.uv, pixel = c.footprint, W, H](const Vec2& s, const Mat2& steps) {
          // The pixel as sub-pixel cells (pixel_sweep.h), each its own footprint with its own half vector.
          const GlintPndf& pndf = f->surface->pndf();
          const std::array<int, 2> cells = pixel_sweep_cells(steps, pndf.sigma_r());
          UvFootprint cell = pixel;
          cell.duv_dx /= cells[0];
          cell.duv_dy /= cells[1];
          Mat2 cell_steps = steps;
          cell_steps.col(0) /= cells[0];
          cell_steps.col(1) /= cells[1];
          double sum = 0.0;
          for (int j = 0; j < cells[1]; ++j)
            for (int i = 0; i < cells[0]; ++i) {
              const Vec2 d((i + 0.5) / cells[0] - 0.5, (j + 0.5) / cells[1] - 0.5);  // in pixel steps
              sum += cell_pndf(pndf, uv + d.x() * pixel.duv_dx + d.y() * pixel.duv_dy, cell, s + steps * d, cell_steps,
                               W, H);
            }
          return sum / double(cells[0] * cells[1]);
        });
      },
      true);
}

}  // namespace mbk
