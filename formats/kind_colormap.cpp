// Asset kind 7, `colormap`: a colour map C (knots, linear RGB colours) and its prefiltered table
// T(sigma_j, m_i) = [C * N(0, sigma_j^2)](m_i) ([Heitz13] Eq. 10; formats/colormap_layout.h). formats/SPEC.md,
// "Kind 7: colormap".
//
// Invariants `validate` checks, in this order (the first finding ends the check): parameters (17002), section
// shapes (17003), finite values (17001), valid knots (17004), then over the table: row 0 equals C at the mean
// samples (17005); every entry inside [min, max] of C's colours per channel, since a Gaussian average of the
// clamp-extended C is a convex combination of its colours (17006); every entry equal to the closed-form
// convolution recomputed in double from the stored knots and colours (17007).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "formats/number_text.h"
#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/colormap_layout.h"

namespace mbk {
namespace {

// The baker computes in double from the float-rounded knots and colours and rounds the result to float once:
// within half an ulp of the largest colour magnitude. Allow 4 half-ulps for libm's erfc/exp differences.
constexpr double kRelativeTolerance = 0x1p-22;

bool good_side(const nlohmann::json& v) {
  return v.is_number_unsigned() && v.get<uint64_t>() >= kColormapMinSide && v.get<uint64_t>() <= kColormapMaxSide;
}

bool finite_number(const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

// The three sections' shapes (from K knots and the parameters' W x H) and finiteness: their data (knots, colours,
// table), or nothing after a finding.
std::optional<std::vector<std::vector<float>>> read_colormap_sections(const Asset& a, const nlohmann::json& p,
                                                                      std::vector<Finding>& out) {
  const SectionInfo& knots_info = a.section(std::string(kColormapKnotsSection));
  const uint64_t K = knots_info.shape.empty() ? 0 : knots_info.shape[0];
  const uint64_t W = p["width"].get<uint64_t>(), H = p["height"].get<uint64_t>();
  const std::pair<std::string_view, std::vector<uint64_t>> shapes[] = {
      {kColormapKnotsSection, {K}}, {kColormapColorsSection, {K, 3}}, {kColormapTableSection, {H, W, 3}}};
  if (K == 0 || K > kColormapMaxKnots) {
    out.push_back(make_finding(msg::colormap_section_shape, "'knots' should be f32 [K] with 1 <= K <= 2^20",
                               {{"section", kColormapKnotsSection}}));
    return std::nullopt;
  }
  for (const auto& [name, shape] : shapes)
    if (a.section(std::string(name)).shape != shape) {
      std::string dims;
      for (uint64_t d : shape) dims += (dims.empty() ? "" : ", ") + number_text(d);
      out.push_back(make_finding(msg::colormap_section_shape,
                                 "'" + std::string(name) + "' should be f32 [" + dims + "]", {{"section", name}}));
      return std::nullopt;
    }
  std::vector<std::vector<float>> data;
  for (const auto& [name, shape] : shapes) {
    data.push_back(a.read<float>(std::string(name)));
    for (size_t i = 0; i < data.back().size(); ++i)
      if (!std::isfinite(data.back()[i])) {
        out.push_back(make_finding(msg::colormap_non_finite, "'" + std::string(name) + "' element " + number_text(i),
                                   {{"section", name}, {"index", i}}));
        return std::nullopt;
      }
  }
  return data;
}

// Every table entry against the curve it was baked from: row 0 is the curve, every entry lies inside the colours'
// range, and rows above 0 are the curve's convolutions.
void check_colormap_table(const ColormapCurve& curve, const ColormapTable& table, const std::vector<float>& T,
                          std::vector<Finding>& out) {
  const uint32_t W = table.width, H = table.height;
  std::array<double, 3> lo, hi;
  double magnitude = 0.0;
  for (int c = 0; c < 3; ++c) {
    lo[c] = hi[c] = curve.colors[0][c];
    for (const auto& color : curve.colors) {
      lo[c] = std::min(lo[c], color[c]);
      hi[c] = std::max(hi[c], color[c]);
    }
    magnitude = std::max({magnitude, std::abs(lo[c]), std::abs(hi[c])});
  }
  const double tolerance = kRelativeTolerance * magnitude;
  auto entry = [&](uint32_t j, uint32_t i, int c) { return double(T[(size_t(j) * W + i) * 3 + c]); };
  auto where = [&](uint32_t j, uint32_t i) {
    return nlohmann::json{{"section", kColormapTableSection}, {"row", j}, {"column", i}};
  };
  auto at = [&](uint32_t j, uint32_t i, int c) {
    return "entry (sigma row " + number_text(j) + ", mean column " + number_text(i) + ") channel " + number_text(c) +
           " is " + number_text(entry(j, i, c));
  };
  for (uint32_t i = 0; i < W; ++i) {
    const auto expected = curve.at(table.mean_at(i));
    for (int c = 0; c < 3; ++c)
      if (std::abs(entry(0, i, c) - expected[c]) > tolerance) {
        out.push_back(make_finding(
            msg::colormap_row0_not_map,
            at(0, i, c) + ", C(" + number_text(table.mean_at(i)) + ") is " + number_text(expected[c]), where(0, i)));
        return;
      }
  }
  for (uint32_t j = 0; j < H; ++j)
    for (uint32_t i = 0; i < W; ++i)
      for (int c = 0; c < 3; ++c)
        if (entry(j, i, c) < lo[c] - tolerance || entry(j, i, c) > hi[c] + tolerance) {
          out.push_back(make_finding(
              msg::colormap_outside_hull,
              at(j, i, c) + ", C's range is [" + number_text(lo[c]) + ", " + number_text(hi[c]) + "]", where(j, i)));
          return;
        }
  for (uint32_t j = 1; j < H; ++j)
    for (uint32_t i = 0; i < W; ++i) {
      const auto expected = curve.convolved(table.mean_at(i), table.sigma_at(j));
      for (int c = 0; c < 3; ++c)
        if (std::abs(entry(j, i, c) - expected[c]) > tolerance) {
          out.push_back(make_finding(msg::colormap_not_convolution,
                                     at(j, i, c) + ", the convolution is " + number_text(expected[c]), where(j, i)));
          return;
        }
    }
}

void check_colormap(const Asset& a, std::vector<Finding>& out) {
  const auto& p = a.metadata()["parameters"];
  if (!p.is_object() || !p.contains("width") || !p.contains("height") || !good_side(p["width"]) ||
      !good_side(p["height"]) || !p.contains("mean_min") || !p.contains("mean_max") || !p.contains("sigma_max") ||
      !finite_number(p["mean_min"]) || !finite_number(p["mean_max"]) || !finite_number(p["sigma_max"]) ||
      !(p["mean_min"].get<double>() < p["mean_max"].get<double>()) || !(p["sigma_max"].get<double>() > 0.0)) {
    out.push_back(make_finding(msg::colormap_bad_parameters, "see parameters", {{"key", "parameters"}}));
    return;
  }
  const std::optional<std::vector<std::vector<float>>> data = read_colormap_sections(a, p, out);
  if (!data) return;
  const uint64_t K = (*data)[0].size();
  ColormapCurve curve;
  for (uint64_t k = 0; k < K; ++k) {
    curve.knots.push_back((*data)[0][k]);
    curve.colors.push_back({(*data)[1][3 * k], (*data)[1][3 * k + 1], (*data)[1][3 * k + 2]});
  }
  if (const std::string problem = colormap_curve_problem(curve); !problem.empty()) {
    out.push_back(make_finding(msg::colormap_bad_knots, problem, {{"section", kColormapKnotsSection}}));
    return;
  }
  ColormapTable table;
  table.width = p["width"].get<uint32_t>();
  table.height = p["height"].get<uint32_t>();
  table.mean_min = p["mean_min"].get<double>();
  table.mean_max = p["mean_max"].get<double>();
  table.sigma_max = p["sigma_max"].get<double>();
  check_colormap_table(curve, table, (*data)[2], out);
}

}  // namespace

AssetKind colormap_kind() {
  AssetKind k;
  k.id = kColormapKindId;
  k.name = "colormap";
  k.summary = "prefiltered colour map: C and C convolved with N(0, sigma^2), indexed by (mean, sigma)";
  k.required_sections = {{std::string(kColormapKnotsSection), {ElementType::f32}, 1},
                         {std::string(kColormapColorsSection), {ElementType::f32}, 2},
                         {std::string(kColormapTableSection), {ElementType::f32}, 3}};
  k.knows_section = [](const std::string& name) {
    return name == kColormapKnotsSection || name == kColormapColorsSection || name == kColormapTableSection;
  };
  k.check_invariants = check_colormap;
  return k;
}

}  // namespace mbk
