// Asset kind 11, `histogram`: a normal map's adaptive bins and the integral images of its per-bin counts, the exact
// binned P-NDF of any footprint ([Shah24] Sec. 4.1 and Eq. 3, [GGN18]; formats/histogram_layout.h). formats/SPEC.md,
// "Kind 11: histogram".
//
// Invariants `validate` checks, in this order (the first finding ends the check): parameters (21001), section types
// and shapes (21002), theta edges 0 = e_0 < ... < e_K = pi/2
// (21003), each centre in its bin and each interior edge the midpoint of its centres (21004), phi edges exactly
// 2 pi i / N (21005), the table's row 0 and column 0 zero (21006); then every one-texel footprint, whose four
// corners give each bin a count >= 0 (21007) that sums to 1 (21008); the whole map's counts summing to W x H,
// and every larger footprint's to its area, follow (a footprint's counts are the sums of its texels').
#include <cmath>
#include <string>
#include <string_view>

#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/histogram_layout.h"
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

// The theta edges (increasing from 0 to the maximum), the theta centres (inside their bins, the edges halfway
// between them) and the phi edges (exactly histogram_phi_edge): true when all hold, else one finding.
bool check_histogram_bins(const Asset& a, uint64_t N, std::vector<Finding>& out) {
  const std::vector<double> edges = a.read<double>(kHistogramThetaEdgesSection);
  const std::vector<double> centres = a.read<double>(kHistogramThetaCentresSection);
  const std::vector<double> phi_edges = a.read<double>(kHistogramPhiEdgesSection);
  const ThetaBinsCheck check = check_theta_bins(edges, centres);
  if (!check.edges_ok) {
    out.push_back(make_finding(msg::histogram_bad_theta_edges, "", {{"section", kHistogramThetaEdgesSection}}));
    return false;
  }
  if (check.bad_centre >= 0) {
    const size_t j = size_t(check.bad_centre);
    out.push_back(make_finding(msg::histogram_bad_theta_centres,
                               "centre " + number_text(j) + " = " + number_text(centres[j]) + ", bin [" +
                                   number_text(edges[j]) + ", " + number_text(edges[j + 1]) + "]",
                               {{"section", kHistogramThetaCentresSection}, {"index", j}}));
    return false;
  }
  for (uint32_t i = 0; i <= N; ++i)
    if (phi_edges[i] != histogram_phi_edge(i, uint32_t(N))) {
      out.push_back(make_finding(msg::histogram_bad_phi_edges, "edge " + number_text(i),
                                 {{"section", kHistogramPhiEdgesSection}, {"index", i}}));
      return false;
    }
  return true;
}

// The summed-area counts: zero on the top row and left column, and every texel's differences non-negative and
// summing to 1 (each texel's normal in exactly one bin).
void check_histogram_counts(const Asset& a, uint64_t W, uint64_t H, uint64_t B, std::vector<Finding>& out) {
  const std::span<const uint8_t> bytes = a.bytes_of(a.section(kHistogramCountsSection));
  const uint32_t* S = reinterpret_cast<const uint32_t*>(bytes.data());
  const uint64_t row = (W + 1) * B;
  auto entry = [&](uint64_t y, uint64_t x) { return S + y * row + x * B; };
  for (uint64_t y = 0; y <= H; ++y)
    for (uint64_t x = 0; x <= W; ++x) {
      if (y > 0 && x > 0) continue;
      for (uint64_t b = 0; b < B; ++b)
        if (entry(y, x)[b] != 0) {
          out.push_back(make_finding(msg::histogram_border_not_zero,
                                     "entry (" + number_text(y) + ", " + number_text(x) + ", " + number_text(b) + ")",
                                     {{"section", kHistogramCountsSection}}));
          return;
        }
    }
  for (uint64_t y = 0; y < H; ++y)
    for (uint64_t x = 0; x < W; ++x) {
      const uint32_t *s00 = entry(y, x), *s01 = entry(y, x + 1), *s10 = entry(y + 1, x), *s11 = entry(y + 1, x + 1);
      int64_t sum = 0;
      for (uint64_t b = 0; b < B; ++b) {
        const int64_t c = int64_t(s11[b]) - s01[b] - s10[b] + s00[b];
        if (c < 0) {
          out.push_back(make_finding(
              msg::histogram_negative_count,
              "texel (" + number_text(x) + ", " + number_text(y) + "), bin " + number_text(b) + ": " + number_text(c),
              {{"section", kHistogramCountsSection}}));
          return;
        }
        sum += c;
      }
      if (sum != 1) {
        out.push_back(
            make_finding(msg::histogram_count_not_area,
                         "texel (" + number_text(x) + ", " + number_text(y) + "): counts sum to " + number_text(sum),
                         {{"section", kHistogramCountsSection}}));
        return;
      }
    }
}

void check_histogram(const Asset& a, std::vector<Finding>& out) {
  const auto& p = a.metadata()["parameters"];
  if (!p.is_object() || !unsigned_in(p, "width", 1, kHistogramMaxSide) ||
      !unsigned_in(p, "height", 1, kHistogramMaxSide) || !unsigned_in(p, "theta_bins", 1, kHistogramMaxThetaBins) ||
      !unsigned_in(p, "theta_bins_requested", 1, kHistogramMaxThetaBins) ||
      !unsigned_in(p, "phi_bins", 1, kHistogramMaxPhiBins) || !p.contains("method") || p["method"] != "exact" ||
      p["theta_bins"].get<uint64_t>() > p["theta_bins_requested"].get<uint64_t>() ||
      (p.contains("theta_binning") && p["theta_binning"] != "adaptive" && p["theta_binning"] != "uniform")) {
    out.push_back(make_finding(msg::histogram_bad_parameters, "see parameters", {{"key", "parameters"}}));
    return;
  }
  const uint64_t W = p["width"].get<uint64_t>(), H = p["height"].get<uint64_t>(), K = p["theta_bins"].get<uint64_t>(),
                 N = p["phi_bins"].get<uint64_t>(), B = K * N;
  const std::pair<const char*, std::vector<uint64_t>> shapes[] = {{kHistogramThetaEdgesSection, {K + 1}},
                                                                  {kHistogramThetaCentresSection, {K}},
                                                                  {kHistogramPhiEdgesSection, {N + 1}},
                                                                  {kHistogramCountsSection, {H + 1, W + 1, B}}};
  for (const auto& [name, shape] : shapes) {
    const SectionInfo* s = a.find(name);
    const ElementType type = std::string_view(name) == kHistogramCountsSection ? ElementType::u32 : ElementType::f64;
    if (!s || s->type != type || s->shape != shape) {
      out.push_back(make_finding(
          msg::histogram_section_shape,
          "'" + std::string(name) + "' should be " + std::string(element_name(type)) + " " + shape_text(shape),
          {{"section", name}}));
      return;
    }
  }
  if (check_histogram_bins(a, N, out)) check_histogram_counts(a, W, H, B, out);
}

}  // namespace

AssetKind histogram_kind() {
  AssetKind k;
  k.id = kHistogramKindId;
  k.name = "histogram";
  k.summary =
      "theta x phi bins of a normal map (adaptive or uniform theta) and integral images of per-bin counts (exact "
      "P-NDF)";
  k.required_sections = {{kHistogramThetaEdgesSection, {ElementType::f64}, 1},
                         {kHistogramThetaCentresSection, {ElementType::f64}, 1},
                         {kHistogramPhiEdgesSection, {ElementType::f64}, 1},
                         {kHistogramCountsSection, {ElementType::u32}, 3}};
  k.knows_section = [](const std::string& name) {
    return name == kHistogramThetaEdgesSection || name == kHistogramThetaCentresSection ||
           name == kHistogramPhiEdgesSection || name == kHistogramCountsSection;
  };
  k.check_invariants = check_histogram;
  return k;
}

}  // namespace mbk
