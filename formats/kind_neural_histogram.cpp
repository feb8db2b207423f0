// Asset kind 12, `neural_histogram`: a normal map's adaptive bins, every texel's bin, a feature pyramid and the
// K + 1 MLPs of [Shah24] Sec. 4.2 / Eq. 11 that predict the binned P-NDF of any footprint of 8 x 8 texels or more
// (formats/neural_histogram_layout.h). formats/SPEC.md, "Kind 12: neural_histogram".
//
// Invariants `validate` checks, in this order (the first finding ends the check): parameters, the pyramid's levels
// included (22001), section types and shapes (22002), theta edges 0 = e_0 < ... < e_K = pi/2 (22003), each centre
// in its bin and each interior edge the midpoint of its centres (22004), every texel's bin below K N (22005), every
// feature and network parameter finite (22006), so that every prediction is a finite probability.
#include <cmath>
#include <string>

#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/neural_histogram_layout.h"
#include "formats/number_text.h"

namespace mbk {
namespace {

bool unsigned_in(const nlohmann::json& p, const char* key, uint64_t lo, uint64_t hi) {
  return p.contains(key) && p[key].is_number_unsigned() && p[key].get<uint64_t>() >= lo && p[key].get<uint64_t>() <= hi;
}

std::string shape_text(const std::vector<uint64_t>& shape) {
  std::string s;
  for (uint64_t d : shape) s += (s.empty() ? "" : ", ") + number_text(d);
  return "[" + s + "]";
}

bool parameters_ok(const nlohmann::json& p) {
  constexpr uint64_t kAny = ~uint64_t(0);
  if (!p.is_object() || !unsigned_in(p, "width", 1, kHistogramMaxSide) ||
      !unsigned_in(p, "height", 1, kHistogramMaxSide) || !unsigned_in(p, "theta_bins", 1, kHistogramMaxThetaBins) ||
      !unsigned_in(p, "theta_bins_requested", 1, kHistogramMaxThetaBins) ||
      !unsigned_in(p, "phi_bins", 1, kHistogramMaxPhiBins) ||
      !unsigned_in(p, "features", 1, kNeuralHistogramMaxFeatures) ||
      !unsigned_in(p, "hidden", 1, kNeuralHistogramMaxHidden) || !unsigned_in(p, "levels", 1, 64) ||
      !unsigned_in(p, "min_footprint", kNeuralHistogramMinFootprint, kNeuralHistogramMinFootprint) ||
      !unsigned_in(p, "iterations", 1, kAny) || !unsigned_in(p, "batch", 1, kAny) || !unsigned_in(p, "seed", 0, kAny) ||
      !unsigned_in(p, "training_seed", 0, kAny) || !p.contains("method") || p["method"] != "neural" ||
      p["theta_bins"].get<uint64_t>() > p["theta_bins_requested"].get<uint64_t>() ||
      (p.contains("theta_binning") && p["theta_binning"] != "adaptive" && p["theta_binning"] != "uniform"))
    return false;
  const NeuralHistogramShape shape{p["width"].get<uint32_t>(),      p["height"].get<uint32_t>(),
                                   p["theta_bins"].get<uint32_t>(), p["phi_bins"].get<uint32_t>(),
                                   p["features"].get<uint32_t>(),   p["hidden"].get<uint32_t>()};
  return p["levels"].get<uint64_t>() == shape.levels();
}

// The index of the first f16 value that is not finite (exponent bits all ones), or -1.
int64_t first_non_finite_half(std::span<const uint8_t> bytes) {
  const uint16_t* h = reinterpret_cast<const uint16_t*>(bytes.data());
  for (size_t i = 0; i < bytes.size() / 2; ++i)
    if ((h[i] & 0x7c00u) == 0x7c00u) return int64_t(i);
  return -1;
}

void check_neural_histogram(const Asset& a, std::vector<Finding>& out) {
  const auto& p = a.metadata()["parameters"];
  if (!parameters_ok(p)) {
    out.push_back(make_finding(msg::neural_histogram_bad_parameters, "see parameters", {{"key", "parameters"}}));
    return;
  }
  const NeuralHistogramShape shape{p["width"].get<uint32_t>(),      p["height"].get<uint32_t>(),
                                   p["theta_bins"].get<uint32_t>(), p["phi_bins"].get<uint32_t>(),
                                   p["features"].get<uint32_t>(),   p["hidden"].get<uint32_t>()};
  const uint64_t K = shape.theta_bins;
  const struct {
    const char* name;
    ElementType type;
    std::vector<uint64_t> shape;
  } sections[] = {{kHistogramThetaEdgesSection, ElementType::f64, {K + 1}},
                  {kHistogramThetaCentresSection, ElementType::f64, {K}},
                  {kNeuralHistogramTexelBinsSection, ElementType::u16, {shape.height, shape.width}},
                  {kNeuralHistogramFeaturesSection, ElementType::f16, {shape.pyramid_texels(), shape.features}},
                  {kNeuralHistogramMlpSection, ElementType::f16, {shape.mlp_parameters()}}};
  for (const auto& s : sections) {
    const SectionInfo* found = a.find(s.name);
    if (!found || found->type != s.type || found->shape != s.shape) {
      out.push_back(make_finding(
          msg::neural_histogram_section_shape,
          "'" + std::string(s.name) + "' should be " + std::string(element_name(s.type)) + " " + shape_text(s.shape),
          {{"section", s.name}}));
      return;
    }
  }
  const std::vector<double> edges = a.read<double>(kHistogramThetaEdgesSection);
  const std::vector<double> centres = a.read<double>(kHistogramThetaCentresSection);
  const ThetaBinsCheck bins = check_theta_bins(edges, centres);
  if (!bins.edges_ok) {
    out.push_back(make_finding(msg::neural_histogram_bad_theta_edges, "", {{"section", kHistogramThetaEdgesSection}}));
    return;
  }
  if (bins.bad_centre >= 0) {
    const size_t j = size_t(bins.bad_centre);
    out.push_back(make_finding(msg::neural_histogram_bad_theta_centres,
                               "centre " + number_text(j) + " = " + number_text(centres[j]) + ", bin [" +
                                   number_text(edges[j]) + ", " + number_text(edges[j + 1]) + "]",
                               {{"section", kHistogramThetaCentresSection}, {"index", j}}));
    return;
  }
  const std::span<const uint8_t> texel_bytes = a.bytes_of(a.section(kNeuralHistogramTexelBinsSection));
  const uint16_t* texel_bins = reinterpret_cast<const uint16_t*>(texel_bytes.data());
  const uint64_t bin_count = K * shape.phi_bins;
  for (uint64_t t = 0; t < uint64_t(shape.width) * shape.height; ++t)
    if (texel_bins[t] >= bin_count) {
      out.push_back(make_finding(msg::neural_histogram_bad_texel_bin,
                                 "texel (" + number_text(t % shape.width) + ", " + number_text(t / shape.width) +
                                     "): bin " + number_text(texel_bins[t]) + " of " + number_text(bin_count),
                                 {{"section", kNeuralHistogramTexelBinsSection}, {"index", t}}));
      return;
    }
  for (const char* name : {kNeuralHistogramFeaturesSection, kNeuralHistogramMlpSection}) {
    const int64_t bad = first_non_finite_half(a.bytes_of(a.section(name)));
    if (bad >= 0) {
      out.push_back(make_finding(msg::neural_histogram_non_finite, "element " + number_text(uint64_t(bad)),
                                 {{"section", name}, {"index", bad}}));
      return;
    }
  }
}

}  // namespace

AssetKind neural_histogram_kind() {
  AssetKind k;
  k.id = kNeuralHistogramKindId;
  k.name = "neural_histogram";
  k.summary =
      "theta x phi bins (adaptive or uniform theta), each texel's bin, a feature pyramid and MLPs predicting "
      "footprint histograms (neural P-NDF)";
  k.required_sections = {{kHistogramThetaEdgesSection, {ElementType::f64}, 1},
                         {kHistogramThetaCentresSection, {ElementType::f64}, 1},
                         {kNeuralHistogramTexelBinsSection, {ElementType::u16}, 2},
                         {kNeuralHistogramFeaturesSection, {ElementType::f16}, 2},
                         {kNeuralHistogramMlpSection, {ElementType::f16}, 1}};
  k.knows_section = [](const std::string& name) {
    return name == kHistogramThetaEdgesSection || name == kHistogramThetaCentresSection ||
           name == kNeuralHistogramTexelBinsSection || name == kNeuralHistogramFeaturesSection ||
           name == kNeuralHistogramMlpSection;
  };
  k.check_invariants = check_neural_histogram;
  return k;
}

}  // namespace mbk
