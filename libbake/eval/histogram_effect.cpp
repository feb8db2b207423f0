// The histogram effect's shaders (see histogram_effect.h).
#include "libbake/eval/histogram_effect.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "formats/asset.h"
#include "formats/error.h"
#include "libbake/core/hash.h"
#include "libbake/eval/band_radiance_grid.h"
#include "libbake/eval/distant_radiance.h"
#include "libbake/eval/roughness_texture.h"
#include "libbake/histogram/binned_ndf_source.h"
#include "libbake/histogram/histogram_pyramid_baseline.h"
#include "libbake/histogram/neural_binned_ndf.h"
#include "libbake/histogram/reflected_lobe.h"
#include "libbake/histogram/roughness_lobe.h"
#include "libbake/histogram/roughness_zh_table.h"
#include "libbake/image/normal_map.h"
#include "libbake/image/texture_taps.h"

namespace mbk {
namespace {

constexpr double kPi = std::numbers::pi;

// What both modes share: the roughness, and the diffuse term of the distant light around the macro normal.
struct Common {
  std::shared_ptr<const RoughnessTexture> roughness;

  Vec3 distant_diffuse(const ShadingContext& c, const Brdf& brdf) const {
    if (!c.lighting->has_distant) return Vec3::Zero();
    return brdf.albedo.cwiseProduct(sh_irradiance(c.lighting->distant, c.frame.N)) / kPi;
  }

  // Diffuse and specular of the point and directional lights for the distribution d(h).
  template <class Distribution>
  Vec3 direct(const ShadingContext& c, const Brdf& brdf, const Distribution& d) const {
    const Vec3& n = c.frame.N;
    const Vec3& v = c.to_viewer;
    Vec3 out = Vec3::Zero();
    for_each_direct_light(*c.lighting, c.position, n, [&](const Vec3& l, const Vec3& e, double) {
      const double cl = n.dot(l);
      if (!(cl > 0.0)) return;
      out += (brdf.albedo / kPi + evaluate_specular(brdf, n, l, v, d)).cwiseProduct(e) * cl;
    });
    return out;
  }
};

std::shared_ptr<const RoughnessTexture> roughness_of(const EffectShaderRequest& request, const std::string& where) {
  const auto file = request.use.files.find("roughness_map");
  if (file == request.use.files.end())
    return std::make_shared<RoughnessTexture>(request.use.options.at("roughness").get<double>());
  const auto image =
      request.cache.get<Image>("roughness map|" + file->second.string(), [&] { return load_image(file->second); });
  return std::make_shared<RoughnessTexture>(image, where + ": roughness_map " + file->second.string());
}

// Each bin's direction in the tangent frame: theta centre j, phi centre 2 pi (i + 1/2) / N.
std::vector<Vec3> bin_directions(const BinnedNdfSource& source) {
  const HistogramBins& bins = source.bins();
  std::vector<Vec3> out;
  out.reserve(bins.count());
  for (const double theta : source.theta_centres())
    for (uint32_t i = 0; i < bins.phi_bins; ++i) {
      const double phi = 2.0 * kPi * (i + 0.5) / bins.phi_bins;
      out.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  return out;
}

class FilteredHistogramShader : public MaterialShader {
 public:
  struct Data {
    Common common;
    std::shared_ptr<const Asset> asset;  // the source reads into it
    std::unique_ptr<const BinnedNdfSource> source;
    std::vector<Vec3> bin_normals;
    std::shared_ptr<const RoughnessZhTable> zh;
    std::shared_ptr<const BandRadianceGrid> grid;  // the distant lighting to order L; null without any
    double narrowest_sigma = 0;                    // narrowest_resolved_roughness(L)
  };
  explicit FilteredHistogramShader(std::shared_ptr<const Data> data) : d_(std::move(data)) {}

  Vec3 radiance(const ShadingContext& c, const Brdf& brdf) const override {
    const Data& d = *d_;
    Vec3 out = d.common.distant_diffuse(c, brdf);
    const Vec3& n = c.frame.N;
    const Vec3& v = c.to_viewer;
    const double cv = n.dot(v);
    if (!(cv > 0.0) || !c.uv.allFinite()) return out;

    const size_t bins = d.bin_normals.size();
    std::vector<double> p(bins, 0.0), q(bins);
    const uint32_t W = d.source->width(), H = d.source->height();
    const FootprintProbes probes = footprint_probes(c.uv, c.footprint, W, H);
    for (const FootprintProbe& probe : probes) {
      const Vec2 t = texel_coordinates(probe.uv, W, H);
      d.source->footprint_probabilities({t.x(), t.y(), probe.width}, q);
      for (size_t b = 0; b < bins; ++b) p[b] += q[b];
    }
    std::vector<Vec3> world(bins);
    for (size_t b = 0; b < bins; ++b) {
      p[b] /= double(probes.size());
      world[b] = c.frame.to_world(d.bin_normals[b]);
    }
    const double sigma = d.common.roughness->at(c.uv);

    out += d.common.direct(c, brdf, [&](const Vec3& h) {
      double sum = 0.0;
      for (size_t b = 0; b < bins; ++b)
        if (p[b] > 0.0) sum += p[b] * roughness_lobe(h.dot(world[b]), sigma);
      return sum;
    });
    if (!d.grid) return out;

    // Eqs. 12-13 and 9: each bin's mirror-image lobes (reflected_lobe.h), rotated zonal lobes dotted with the
    // lighting's SH, lobe by lobe through the band radiance grid; F and G2 at each lobe's own half vector.
    std::vector<double> lambda(size_t(d.grid->order()) + 1);
    Vec3 specular = Vec3::Zero();
    for (size_t b = 0; b < bins; ++b) {
      if (!(p[b] > 0.0) || !(world[b].dot(v) > 0.0)) continue;
      const ReflectedLobes lobes = reflected_lobes(world[b], v, sigma);
      d.zh->band_factors(std::max(lobes.table_sigma, d.narrowest_sigma), lambda);
      for (int i = 0; i < lobes.count; ++i) {
        const Vec3& r = lobes.axes[size_t(i)];
        const double crn = r.dot(n), chv = lobes.view_cosines[size_t(i)];
        if (!(crn > 0.0 && chv > 0.0)) continue;  // below the macro surface, or a half vector facing away
        const double g = p[b] * lobes.weights[size_t(i)] * smith_g2(brdf.lobe, crn, cv) * chv / cv;
        specular += g * schlick_fresnel(brdf.f0, chv).cwiseProduct(d.grid->lobe_radiance(r, lambda));
      }
    }
    out += specular.cwiseMax(0.0);
    return out;
  }

 private:
  std::shared_ptr<const Data> d_;
};

class ReferenceHistogramShader : public MaterialShader {
 public:
  struct Data {
    Common common;
    std::shared_ptr<const LoadedNormalMap> map;
    DistantRadiance distant;
  };
  explicit ReferenceHistogramShader(std::shared_ptr<const Data> data) : d_(std::move(data)) {}

  Vec3 radiance(const ShadingContext& c, const Brdf& brdf) const override {
    const Data& d = *d_;
    Vec3 out = d.common.distant_diffuse(c, brdf);
    const Vec3& n = c.frame.N;
    const Vec3& v = c.to_viewer;
    const double cv = n.dot(v);
    if (!(cv > 0.0) || !c.uv.allFinite()) return out;

    // The texel the exact uv falls in (Eq. 2's omega_x).
    const NormalMap& map = d.map->map;
    const Vec2 t = texel_coordinates(c.uv, map.width, map.height);
    const uint32_t x = std::min(uint32_t(t.x()), map.width - 1), row = std::min(uint32_t(t.y()), map.height - 1);
    const Vec3 w = c.frame.to_world(map.at(x, row).cast<double>()).normalized();
    const double sigma = d.common.roughness->at(c.uv);

    out += d.common.direct(c, brdf, [&](const Vec3& h) { return roughness_lobe(h.dot(w), sigma); });
    if (d.distant.empty()) return out;

    const uint64_t ub = std::bit_cast<uint64_t>(c.uv.x()), vb = std::bit_cast<uint64_t>(c.uv.y());
    const uint32_t seed = hash4(uint32_t(ub), uint32_t(ub >> 32), uint32_t(vb), uint32_t(vb >> 32));
    Vec3 sum = Vec3::Zero();
    for (int k = 0; k < kHistogramReferenceLobeSamples; ++k) {
      const double u1 = (k + unit_from_hash(hash_combine(seed, uint32_t(2 * k)))) / kHistogramReferenceLobeSamples;
      const double u2 = unit_from_hash(hash_combine(seed, uint32_t(2 * k + 1)));
      const Vec3 h = sample_roughness_lobe(w, sigma, u1, u2);
      const double chv = h.dot(v);
      if (!(chv > 0.0)) continue;
      const Vec3 wi = 2.0 * chv * h - v;
      const double cin = wi.dot(n);
      if (!(cin > 0.0)) continue;
      sum += d.distant.radiance(wi).cwiseProduct(schlick_fresnel(brdf.f0, chv)) *
             (smith_g2(brdf.lobe, cin, cv) * chv / cv);
    }
    return out + sum / double(kHistogramReferenceLobeSamples);
  }

 private:
  std::shared_ptr<const Data> d_;
};

}  // namespace

ShaderPtr histogram_effect_shader(const EffectShaderRequest& request) {
  const std::string where = "materials." + request.material.name + ": histogram";
  if (!request.material.normal_map)
    throw Error(ExitCode::invalid_input, "the histogram effect needs the material's normal map", where);
  Common common{roughness_of(request, where)};

  if (request.mode == EvalMode::reference) {
    auto data = std::make_shared<ReferenceHistogramShader::Data>();
    data->common = common;
    const NormalMapRef& ref = *request.material.normal_map;
    const std::string key = "histogram normals|" + ref.path.string() + "|" + convention_request_name(ref.convention) +
                            (ref.repair ? "|repair" : "|error");
    data->map = request.cache.get<LoadedNormalMap>(key, [&] { return load_normal_map(ref.path, ref.load_options()); });
    data->distant = DistantRadiance::load(request.scene, request.cache);
    return std::make_shared<ReferenceHistogramShader>(data);
  }

  auto data = std::make_shared<FilteredHistogramShader::Data>();
  data->common = common;
  const std::filesystem::path& file = request.assets.at(0);
  data->asset = request.cache.get<Asset>("asset|" + file.string(), [&] { return Asset::open(file); });
  if (data->asset->kind().name == std::string_view("neural_histogram")) {
    data->source = open_neural_histogram(*data->asset);
  } else if (request.use.options.at("method") == "pyramid") {
    HistogramAssetView view = histogram_asset_view(*data->asset);
    const NeuralHistogramShape shape{view.table.width,
                                     view.table.height,
                                     view.bins.theta_bins(),
                                     view.bins.phi_bins,
                                     request.use.options.at("features").get<uint32_t>(),
                                     kNeuralHistogramHidden};
    data->source = std::make_unique<HistogramPyramidBaseline>(std::move(view), neural_predictor_bytes(shape));
  } else {
    data->source = std::make_unique<ExactBinnedNdf>(histogram_asset_view(*data->asset));
  }
  data->bin_normals = bin_directions(*data->source);
  const int order = request.use.options.at("sh_order").get<int>();
  const DistantRadiance distant = DistantRadiance::load(request.scene, request.cache);
  if (!distant.empty()) {
    data->zh = request.cache.get<RoughnessZhTable>("roughness zh|" + std::to_string(order),
                                                   [&] { return RoughnessZhTable(order); });
    data->grid = request.cache.get<BandRadianceGrid>("band radiance|" + std::to_string(order),
                                                     [&] { return BandRadianceGrid(distant.sh(order)); });
    data->narrowest_sigma = narrowest_resolved_roughness(order);
  }
  return std::make_shared<FilteredHistogramShader>(data);
}

}  // namespace mbk
