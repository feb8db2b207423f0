// The colour-map effect shaders (see colormap_effect.h).
#include "libbake/eval/colormap_effect.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "formats/asset.h"
#include "formats/error.h"
#include "libbake/colormap/colormap_reference.h"
#include "libbake/colormap/colormap_shading.h"
#include "libbake/colormap/colormap_source.h"
#include "libbake/colormap/moment_pyramid.h"
#include "libbake/colormap/noise_statistics.h"
#include "libbake/core/gauss_legendre.h"
#include "libbake/gen/periodic_noise.h"

namespace mbk {
namespace {

enum class Case { texture, height, slope };

// The driver f, mapped as offset + scale * f.
struct DriverSource {
  std::shared_ptr<const MomentPyramid> pyramid;  // image driver (all levels filtered; level 0 for the reference)
  std::shared_ptr<const NoiseFootprintTable> noise_table;
  NoiseParameters noise;
  double scale = 1.0, offset = 0.0;

  NoiseFootprint statistics(const Vec2& uv, const UvFootprint& f) const {
    NoiseFootprint s;
    if (pyramid) {
      // The footprint's moments from its probes': E[d] and E[d^2] are means over the footprint.
      const Image& l0 = pyramid->levels.at(0);
      const FootprintProbes probes = footprint_probes(uv, f, l0.width, l0.height);
      double mean = 0.0, second = 0.0;
      for (const FootprintProbe& p : probes) {
        const FootprintMoments m = sample_moments(*pyramid, p.uv, p.lod);
        mean += m.mean / probes.size();
        second += (m.variance + m.mean * m.mean) / probes.size();
      }
      s = {mean, std::max(0.0, second - mean * mean)};
    } else {
      const Vec2 box(std::abs(f.duv_dx.x()) + std::abs(f.duv_dy.x()), std::abs(f.duv_dx.y()) + std::abs(f.duv_dy.y()));
      // A grazing ray's footprint is unbounded: the noise's statistics at a footprint far above its cell size.
      s = fbm_footprint(*noise_table, noise, uv, box.array().isFinite().all() ? box : Vec2(1e6, 1e6));
    }
    return {offset + scale * s.mean, scale * scale * s.variance};
  }
  double at_point(const Vec2& uv) const {
    const double f = pyramid ? sample_moments(*pyramid, uv, 0.0).mean
                             : periodic_fbm(uv, noise.cells_x, noise.cells_y, noise.octaves, noise.gain, noise.seed);
    return offset + scale * f;
  }
};

struct Settings {
  Case which = Case::texture;
  bool naive = false;
  std::shared_ptr<const ColormapTable> table;  // filtered mode
  std::shared_ptr<const ColormapCurve> curve;  // reference mode
  std::optional<DriverSource> driver;          // texture and height cases
  Microsurface surface;                        // height and slope cases (height_offset 0: the driver shifts)
  Vec2 direction = Vec2::UnitX();              // slope case
  double slope_offset = 0.5;
  double weight = 1.0;  // kappa of Sec. 6's linear combination
};

// Quadrature of a standard normal over +-`extent` standard deviations: nodes z with weights phi(z) dz.
std::vector<QuadratureNode> normal_quadrature(double extent, int panels, int order) {
  std::vector<QuadratureNode> nodes = composite_gauss_legendre(-extent, extent, panels, order);
  for (auto& n : nodes) n.w *= std::exp(-0.5 * n.x * n.x) / std::sqrt(2.0 * std::numbers::pi);
  return nodes;
}

// w in the local frame (T, B, N). Where the tangents are undefined (a sphere's poles) any tangents do: the
// isotropic microsurfaces are the same in every frame there.
Vec3 local(const SurfaceFrame& frame, const Vec3& w) {
  Vec3 t = frame.T, b = frame.B;
  if (!t.allFinite() || !b.allFinite() || t.squaredNorm() < 0.5) {
    t = frame.N.unitOrthogonal();
    b = frame.N.cross(t);
  }
  Vec3 l(w.dot(t), w.dot(b), w.dot(frame.N));
  l.z() = std::max(l.z(), 1e-4);  // directions at or below the horizon: Lambda stays finite (the shading is ~0)
  return l.normalized();
}

Vec3 light_direction(const ShadingContext& c) {
  const SceneLighting& l = *c.lighting;
  if (!l.directionals.empty()) return local(c.frame, -l.directionals.front().direction);
  if (!l.points.empty()) return local(c.frame, (l.points.front().position - c.position).normalized());
  return Vec3::UnitZ();
}

// One colour-map effect's term of the material's colour: C0_bar, Ch_bar (carrying V_bar) or Cs_bar.
class ColormapTerm {
 public:
  explicit ColormapTerm(Settings s) : s_(std::move(s)) {}
  Case which() const { return s_.which; }
  double weight() const { return s_.weight; }
  const Mat2& slope_covariance() const { return s_.surface.slopes.covariance; }

  // The term at the shading point into `terms` (the height case also sets V_bar).
  void evaluate(const ShadingContext& c, ColormapTerms& terms) const {
    if (s_.table) {
      filtered(c, terms);
    } else {
      reference(c, terms);
    }
  }

 private:
  void filtered(const ShadingContext& c, ColormapTerms& t) const {
    const ColormapFiltering mode = s_.naive ? ColormapFiltering::naive : ColormapFiltering::filtered;
    if (s_.which == Case::slope) {
      t.cs = slope_colormap(*s_.table, s_.surface, s_.direction, s_.slope_offset, local(c.frame, c.to_viewer), mode);
      return;
    }
    const NoiseFootprint f = s_.driver->statistics(c.uv, c.footprint);
    if (s_.which == Case::texture) {
      t.c0 = texture_colormap(*s_.table, f.mean, std::sqrt(f.variance), mode);
      return;
    }
    const HeightColormap h = height_colormap(*s_.table, s_.surface, local(c.frame, c.to_viewer), light_direction(c),
                                             mode, f.mean, f.variance);
    t.ch = h.color;
    t.visibility = h.visibility;
  }

  void reference(const ShadingContext& c, ColormapTerms& t) const {
    // Heights: 256 nodes over +-8 sigma_h (D_h moves up to ~3 sigma_h at grazing angles); slopes: a 48 x 48
    // grid over +-6 sigma (the 2-D integral is the costly one).
    static const std::vector<QuadratureNode> z = normal_quadrature(8.0, 32, 8), zs = normal_quadrature(6.0, 12, 4);
    if (s_.which == Case::texture) {
      t.c0 = arr(s_.curve->at(s_.driver->at_point(c.uv)));
      return;
    }
    const Vec3 wo = local(c.frame, c.to_viewer);
    const Mat2& cov = s_.surface.slopes.covariance;
    if (s_.which == Case::height) {
      const double sigma_h = s_.surface.sigma_h, lo = smith_lambda(wo, cov), li = smith_lambda(light_direction(c), cov);
      std::vector<WeightedValue> heights;
      for (const auto& n : z) heights.push_back({sigma_h * n.x, n.w});
      // Eq. (14) at the point: its denominator integrates the whole height law, so it does not depend on the
      // driver and the pixel's average of these ratios is Eq. (14) over the footprint.
      t.ch = reference_height_colormap(*s_.curve, heights, sigma_h, s_.driver->at_point(c.uv), lo, li);
      t.visibility = averaged_visibility(lo, li);
      return;
    }
    const double sx = std::sqrt(cov(0, 0)), sy = std::sqrt(cov(1, 1));
    std::vector<WeightedSlope> slopes;
    for (const auto& a : zs)
      for (const auto& b : zs) slopes.push_back({s_.surface.slopes.mean + Vec2(sx * a.x, sy * b.x), a.w * b.w});
    t.cs = reference_slope_colormap(*s_.curve, slopes, s_.direction, s_.slope_offset, wo);
  }

  static Vec3 arr(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

  Settings s_;
};

// The material's albedo from its colour-map effects, combined as Sec. 6 says (combine_colormaps), shading through
// the shader the first of them wrapped.
class ColormapShader : public MaterialShader {
 public:
  ColormapShader(std::vector<ColormapTerm> terms, bool product, ShaderPtr base)
      : terms_(std::move(terms)), base_(std::move(base)) {
    weights_.product = product;
    weights_.k0 = 0.0;
    for (const ColormapTerm& t : terms_)
      (t.which() == Case::texture ? weights_.k0 : t.which() == Case::height ? weights_.k1 : weights_.k2) = t.weight();
  }

  Vec3 radiance(const ShadingContext& c, const Brdf& brdf) const override {
    ColormapTerms terms;  // absent terms: ones (product) and weight 0 (linear)
    for (const ColormapTerm& t : terms_) t.evaluate(c, terms);
    Brdf coloured = brdf;
    coloured.albedo = combine_colormaps(terms, weights_);
    return base_->radiance(c, coloured);
  }

  bool uses_normal_steps() const override { return base_->uses_normal_steps(); }

  const std::vector<ColormapTerm>& terms() const { return terms_; }
  bool product() const { return weights_.product; }
  const ShaderPtr& base() const { return base_; }

 private:
  std::vector<ColormapTerm> terms_;
  ColormapWeights weights_;
  ShaderPtr base_;
};

ShaderPtr make_colormap_shader(const EffectShaderRequest& request, Case which) {
  const nlohmann::json& o = request.use.options;
  Settings s;
  s.which = which;
  s.naive = o.at("mode") == "naive";
  if (request.mode == EvalMode::filtered) {
    const std::filesystem::path& file = request.assets.at(0);
    s.table = request.cache.get<ColormapTable>("colormap asset|" + file.string(),
                                               [&] { return read_colormap_table(Asset::open(file)); });
  } else {
    const std::filesystem::path& map = request.use.files.at("colormap");
    s.curve = request.cache.get<ColormapCurve>(
        "colormap source|" + map.string(), [&] { return load_colormap_source(map, ColorEncoding::automatic).curve; });
  }
  if (which != Case::slope) {
    DriverSource d;
    d.scale = o.at("scale");
    d.offset = o.at("offset");
    if (request.use.files.count("driver")) {
      const std::filesystem::path driver = request.use.files.at("driver");
      d.pyramid =
          request.mode == EvalMode::filtered
              ? request.cache.get<MomentPyramid>("moments asset|" + request.assets.at(1).string(),
                                                 [&] { return read_moment_pyramid(Asset::open(request.assets.at(1))); })
              : request.cache.get<MomentPyramid>("driver moments|" + driver.string(),
                                                 [&] { return build_moment_pyramid(load_driver(driver, 0)); });
    } else {
      const nlohmann::json& n = o.at("noise");
      d.noise = {n.at("cells")[0], n.at("cells")[1], n.at("octaves"), n.at("gain"), n.at("seed")};
      d.noise_table =
          request.cache.get<NoiseFootprintTable>("noise footprint table", [] { return NoiseFootprintTable(); });
    }
    s.driver = d;
  }
  const double slope_sigma = o.value("slope_sigma", 0.3);
  s.surface.height_offset = 0.0;
  s.surface.sigma_h = o.value("sigma_h", 0.0);
  s.surface.slopes.covariance = Mat2::Identity() * slope_sigma * slope_sigma;
  const double angle = o.value("direction_degrees", 0.0) * std::numbers::pi / 180.0;
  s.direction = Vec2(std::cos(angle), std::sin(angle));
  s.slope_offset = o.value("offset", 0.5);
  s.weight = o.at("weight");
  const bool product = o.at("combine") == "product";
  // A second colour-map effect of the material joins the first one's shader (Sec. 6).
  if (const auto first = std::dynamic_pointer_cast<const ColormapShader>(request.base)) {
    if (first->product() != product)
      throw Error(ExitCode::invalid_input,
                  "the colour-map effects of one material must combine the same way (linear or product)",
                  "materials." + request.material.name + ": " + request.use.name + ".combine");
    std::vector<ColormapTerm> terms = first->terms();
    // Sec. 6 shades one microsurface: V_bar (height effect) and C_s_bar (slope effect) must see the same slopes.
    for (const ColormapTerm& t : terms)
      if (t.which() != Case::texture && s.which != Case::texture && t.slope_covariance() != s.surface.slopes.covariance)
        throw Error(ExitCode::invalid_input,
                    "the height and slope colour-map effects of one material describe one microsurface: give them "
                    "the same slope_sigma",
                    "materials." + request.material.name + ": " + request.use.name + ".slope_sigma");
    terms.emplace_back(std::move(s));
    return std::make_shared<ColormapShader>(std::move(terms), product, first->base());
  }
  return std::make_shared<ColormapShader>(std::vector<ColormapTerm>{ColormapTerm(std::move(s))}, product, request.base);
}

}  // namespace

ShaderPtr colormap_effect_shader(const EffectShaderRequest& r) { return make_colormap_shader(r, Case::texture); }
ShaderPtr colormap_height_effect_shader(const EffectShaderRequest& r) { return make_colormap_shader(r, Case::height); }
ShaderPtr colormap_slope_effect_shader(const EffectShaderRequest& r) { return make_colormap_shader(r, Case::slope); }

}  // namespace mbk
