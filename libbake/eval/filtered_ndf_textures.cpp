// Trilinear lookups in `sh` and `vmf` assets (see filtered_ndf_textures.h).
#include "libbake/eval/filtered_ndf_textures.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "formats/error.h"
#include "libbake/eval/vmf_lobe_merge.h"
#include "libbake/image/texture_taps.h"

namespace mbk {
namespace {

void require_kind(const Asset& asset, std::string_view kind) {
  if (asset.kind().name != kind)
    throw Error(
        ExitCode::invalid_input,
        "asset of kind '" + std::string(asset.kind().name) + "' where a '" + std::string(kind) + "' asset is needed",
        asset.where());
}

bool finite(const Vec2& uv, double lod) { return std::isfinite(uv.x()) && std::isfinite(uv.y()) && !std::isnan(lod); }

}  // namespace

ShNdfTexture ShNdfTexture::from_asset(const Asset& asset) {
  require_kind(asset, "sh");
  const auto& p = asset.metadata()["parameters"];
  ShNdfTexture t(p["order"].get<int>());
  t.width_ = p["width"].get<uint32_t>();
  t.height_ = p["height"].get<uint32_t>();
  t.normals_ = asset.read<float>("normals");
  for (float w : asset.read<float>("window")) t.window_.push_back(w);
  const size_t levels = p["levels"].get<size_t>();
  for (size_t k = 1; k < levels; ++k) {
    const SectionInfo& s = asset.section("level_" + std::to_string(k));
    t.heights_.push_back(uint32_t(s.shape[0]));
    t.widths_.push_back(uint32_t(s.shape[1]));
    t.levels_.push_back(asset.read_as_float("level_" + std::to_string(k)));
  }
  return t;
}

void ShNdfTexture::add_level(size_t level, const Vec2& uv, double weight, std::span<double> g,
                             FinestDelta* finest) const {
  const size_t count = size_t(basis_.count());
  if (level == 0) {
    // One delta at the renormalised bilinear normal, as plain normal mapping and the reference shade (see the
    // header; test: FilteredNdfEffects.MagnifiedBumpyMapMatchesPlainNormalMapping).
    Vec3 n = Vec3::Zero();
    for (const TextureTap& tap : bilinear_taps(width_, height_, uv)) {
      const float* t = &normals_[(size_t(tap.row) * width_ + tap.x) * 3];
      n += tap.weight * Vec3(t[0], t[1], t[2]);
    }
    const double len = n.norm();
    const Vec3 normal = len > 1e-6 ? Vec3(n / len) : Vec3::UnitZ();  // opposite taps: the mean lost its direction
    std::vector<double> y(count);
    basis_.evaluate(normal, y);
    for (size_t k = 0; k < count; ++k) g[k] += weight * y[k];
    if (finest) *finest = {weight, normal};
    return;
  }
  const uint32_t w = widths_[level - 1], h = heights_[level - 1];
  for (const TextureTap& tap : bilinear_taps(w, h, uv)) {
    const float* c = &levels_[level - 1][(size_t(tap.row) * w + tap.x) * count];
    for (size_t k = 0; k < count; ++k) g[k] += weight * tap.weight * c[k];
  }
}

void ShNdfTexture::lookup(const Vec2& uv, double lod, std::span<double> g, FinestDelta* finest) const {
  const size_t count = size_t(basis_.count());
  if (g.size() < count) throw Error(ExitCode::runtime_failure, "internal: SH lookup span shorter than the basis");
  if (!finite(uv, lod)) {
    std::fill(g.begin(), g.begin() + long(count), std::numeric_limits<double>::quiet_NaN());
    return;
  }
  std::fill(g.begin(), g.begin() + long(count), 0.0);
  if (finest) *finest = {};
  const LevelBlend b = level_blend(levels(), lod);
  add_level(b.fine, uv, 1.0 - b.t, g, finest);
  if (b.t > 0.0) add_level(b.coarse, uv, b.t, g, finest);
}

VmfTexture VmfTexture::from_asset(const Asset& asset) {
  require_kind(asset, "vmf");
  const auto& p = asset.metadata()["parameters"];
  VmfTexture t;
  t.lobes_ = p["lobes"].get<int>();
  t.features_ = p["feature_channels"].get<int>();
  t.kappa_max_ = p["kappa_max"].get<double>();
  const size_t levels = p["levels"].get<size_t>();
  for (size_t k = 0; k < levels; ++k) {
    const SectionInfo& s = asset.section("level_" + std::to_string(k));
    t.heights_.push_back(uint32_t(s.shape[0]));
    t.widths_.push_back(uint32_t(s.shape[1]));
    t.levels_.push_back(asset.read<float>("level_" + std::to_string(k)));
    if (t.features_) t.feature_levels_.push_back(asset.read<float>("features_" + std::to_string(k)));
  }
  return t;
}

size_t VmfTexture::box_level(double width) const {
  // The coarsest level whose texels (widths_[0] / widths_[k] by heights_[0] / heights_[k] finest texels: 2^k on
  // power-of-two sides) are at most a quarter of the width on both axes; 0 (no box read) where level 1's are wider
  // already. The box then spans at most ~8 of its texels per axis, or the whole level where that is smaller
  // (box_taps folds the wrap), so a read touches at most ~81 texels whatever the width.
  size_t level = 0;
  for (size_t k = 1; k < levels(); ++k) {
    const double texel = std::max(double(widths_[0]) / double(widths_[k]), double(heights_[0]) / double(heights_[k]));
    if (!(texel <= width / kVmfBoxTexelsPerWidth)) break;
    level = k;
  }
  return level;
}

std::vector<VmfLobeShape> VmfTexture::lookup(const Vec2& uv, double lod, std::vector<double>* features) const {
  FootprintProbes probe;
  probe.push_back({uv, lod});
  return lookup(probe, features);
}

std::vector<VmfLobeShape> VmfTexture::lookup(const FootprintProbes& probes, std::vector<double>* features) const {
  const size_t J = size_t(lobes_), F = size_t(features_);
  // Each probe of a box width w (see the header): at least 8 texels wide, the texels its box covers at the
  // coarsest level whose texels are at most w / 4 (box_level), weighted by their overlap; narrower, its quarters,
  // 2 x 2 trilinear lookups of width w / 2 at +-w / 4 along the texel axes, one level finer, each with a quarter of
  // the probe's weight. A probe of no finite width, or not finite itself, is read as it is.
  struct Read {
    FootprintProbe at;
    double weight;
  };
  // The texels of levels >= 1 the lookup touches, with their summed weights (neighbouring reads share most of
  // their coarse texels: summed after sorting below), and each read's level-0 part as one delta:
  // [alpha, alpha n, alpha y].
  struct TexelWeight {
    size_t level, texel;
    double weight;
  };
  std::vector<TexelWeight> texels;
  std::vector<Read> reads;
  const double probe_weight = 1.0 / double(probes.size());
  for (const FootprintProbe& p : probes) {
    if (!(p.width > 0.0) || !std::isfinite(p.width) || !finite(p.uv, p.lod)) {
      reads.push_back({p, probe_weight});
      continue;
    }
    if (const size_t level = box_level(p.width); level > 0) {
      const uint32_t w = widths_[level], h = heights_[level];
      const double half_x = 0.5 * p.width * w / widths_[0], half_y = 0.5 * p.width * h / heights_[0];
      for (const TextureTap& tap : box_taps(w, h, p.uv, half_x, half_y))
        texels.push_back({level, size_t(tap.row) * w + tap.x, probe_weight * tap.weight});
      continue;
    }
    const Vec2 step(0.25 * p.width / widths_[0], 0.25 * p.width / heights_[0]);
    for (const double dy : {-1.0, 1.0})
      for (const double dx : {-1.0, 1.0})
        reads.push_back({{p.uv + Vec2(dx * step.x(), dy * step.y()), std::max(0.0, p.lod - 1.0), 0.5 * p.width},
                         0.25 * probe_weight});
  }
  bool all_finite = true, finest = false;
  for (const auto& [p, weight] : reads) {
    all_finite = all_finite && finite(p.uv, p.lod);
    finest = finest || (finite(p.uv, p.lod) && level_blend(levels(), p.lod).fine == 0);
  }
  const size_t slots = J + (finest ? 1 : 0);
  if (!all_finite || (reads.empty() && texels.empty())) {
    if (features) features->assign(slots * F, 0.0);
    return std::vector<VmfLobeShape>(slots);
  }
  std::vector<double> deltas;
  const size_t delta_size = 4 + F;
  std::vector<double> delta(delta_size);
  for (const auto& [p, read_weight] : reads) {
    const LevelBlend b = level_blend(levels(), p.lod);
    std::fill(delta.begin(), delta.end(), 0.0);
    for (const auto& [level, blend] : {std::pair{b.fine, 1.0 - b.t}, std::pair{b.coarse, b.t}}) {
      if (blend == 0.0) continue;
      const double weight = blend * read_weight;
      const uint32_t w = widths_[level];
      for (const TextureTap& tap : bilinear_taps(w, heights_[level], p.uv)) {
        const size_t texel = size_t(tap.row) * w + tap.x;
        if (level == 0) {
          for (size_t q = 0; q < J * 4; ++q) delta[q % 4] += weight * tap.weight * levels_[0][texel * J * 4 + q];
          for (size_t q = 0; q < J * F; ++q)
            delta[4 + q % F] += weight * tap.weight * feature_levels_[0][texel * J * F + q];
          continue;
        }
        texels.push_back({level, texel, weight * tap.weight});
      }
    }
    if (!(delta[0] > 0.0)) continue;
    // Level 0 holds one lobe (1, n) per texel, in whichever slot the coherence pass chose. Blending the taps
    // per slot (Alg. 7.2) would shade two or more lobes between unequal neighbours, or one whose |r| < 1 reads
    // as a spread; plain normal mapping and the reference shade the renormalised interpolated normal. So a
    // read's level-0 part is one delta: alpha = its weight, r = the interpolated normal rescaled to length alpha
    // (kappa_max). Deviation [Han07]: Alg. 7.2 blends level 0 like any other level (test:
    // FilteredNdfEffects.MagnifiedBumpyMapMatchesPlainNormalMapping).
    const double len = std::sqrt(delta[1] * delta[1] + delta[2] * delta[2] + delta[3] * delta[3]);
    if (len > 1e-6 * delta[0])
      for (int a = 1; a <= 3; ++a) delta[size_t(a)] *= delta[0] / len;
    deltas.insert(deltas.end(), delta.begin(), delta.end());
  }
  // One entry per texel, in (level, texel) order (deterministic whatever order the reads touched them in).
  std::sort(texels.begin(), texels.end(), [](const TexelWeight& a, const TexelWeight& b) {
    return a.level != b.level ? a.level < b.level : a.texel < b.texel;
  });
  size_t unique = 0;
  for (size_t i = 0; i < texels.size(); ++i) {
    if (unique > 0 && texels[unique - 1].level == texels[i].level && texels[unique - 1].texel == texels[i].texel)
      texels[unique - 1].weight += texels[i].weight;
    else
      texels[unique++] = texels[i];
  }
  texels.resize(unique);
  // Every texel's lobes and every delta, merged by direction (vmf_lobe_merge.h; deviation [Han07]: Alg. 7.2
  // blends slot by slot).
  std::vector<double> scaled_features(texels.size() * J * F);
  std::vector<WeightedVmfLobe> candidates;
  for (size_t t = 0; t < texels.size(); ++t) {
    const TexelWeight& tw = texels[t];
    const float* lobe = &levels_[tw.level][tw.texel * J * 4];
    for (size_t j = 0; j < J; ++j, lobe += 4) {
      if (!(lobe[0] > 0.0f)) continue;
      double* y = &scaled_features[(t * J + j) * F];
      for (size_t f = 0; f < F; ++f) y[f] = tw.weight * feature_levels_[tw.level][(tw.texel * J + j) * F + f];
      candidates.push_back({tw.weight * lobe[0], tw.weight * Vec3(lobe[1], lobe[2], lobe[3]), std::span(y, F), t});
    }
  }
  for (size_t d = 0; d * delta_size < deltas.size(); ++d) {
    const double* delta = &deltas[d * delta_size];
    candidates.push_back({delta[0], Vec3(delta[1], delta[2], delta[3]), std::span(delta + 4, F), texels.size() + d});
  }
  std::vector<double> alpha_y;
  std::vector<VmfLobeShape> lobes = merge_vmf_lobes(candidates, slots, kappa_max_, F, features ? &alpha_y : nullptr);
  if (features) {
    features->assign(slots * F, 0.0);
    for (size_t j = 0; j < slots; ++j)
      if (lobes[j].alpha > 0.0)
        for (size_t f = 0; f < F; ++f) (*features)[j * F + f] = alpha_y[j * F + f] / lobes[j].alpha;
  }
  return lobes;
}

}  // namespace mbk
