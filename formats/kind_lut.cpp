// Asset kind 2, `lut`: the standardization tables of an example normal map for histogram-preserving blending
// ([Wang20] Eq. 6, [Heitz18] Sec. 3): per channel n_x, n_y the forward table G on [x_lo, x_hi], the inverse
// table G^-1 on [z_lo, z_hi], and their slope tables (formats/lut_layout.h). formats/SPEC.md, "Kind 2: lut".
//
// Invariants `validate` checks, in this order (the first finding ends the check): parameters (12002), section
// shapes (12003), finite values (12001), then per channel and table: a domain with lo <= hi, constant when
// lo == hi (12004); end values equal to the other table's domain (12008: forward runs from z_lo to z_hi, inverse
// from x_lo to x_hi, so both describe one mapping); non-decreasing values (12005); non-negative slopes (12006);
// slopes equal to the interpolant's, recomputed in double from the stored floats, within float rounding (12007).
#include <cmath>
#include <limits>
#include <string>

#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/lut_layout.h"

namespace mbk {
namespace {

// A stored slope is the double slope rounded to float: within half an ulp, i.e. 2^-24 relative; allow 2^-23, plus
// the smallest subnormal for slopes that round into float's subnormal range.
constexpr double kSlopeRelativeTolerance = 0x1p-23;
constexpr double kSlopeAbsoluteTolerance = std::numeric_limits<float>::denorm_min();

struct Table {
  const char* name;        // "forward" or "inverse"
  const char* slope_name;  // its slope section
  double lo, hi;           // its domain
  double first, last;      // what its end values must be: the other table's domain
  const float* values;
  const float* slopes;
};

void check_table(const Table& t, uint32_t size, uint32_t channel, std::vector<Finding>& out) {
  const std::string at = std::string(kLutChannelNames[channel]) + " " + t.name;
  const nlohmann::json where = {{"section", t.name}, {"channel", kLutChannelNames[channel]}};
  auto at_index = [&](const char* section, uint32_t j) {
    return nlohmann::json{{"section", section}, {"channel", kLutChannelNames[channel]}, {"index", j}};
  };
  if (t.lo > t.hi) {
    out.push_back(make_finding(msg::lut_bad_domain,
                               at + ": lo " + std::to_string(t.lo) + " > hi " + std::to_string(t.hi), where));
    return;
  }
  if (t.lo == t.hi)
    for (uint32_t j = 1; j < size; ++j)
      if (t.values[j] != t.values[0]) {
        out.push_back(make_finding(msg::lut_bad_domain,
                                   at + ": empty domain [" + std::to_string(t.lo) + ", " + std::to_string(t.hi) +
                                       "] but sample " + std::to_string(j) + " differs from sample 0",
                                   at_index(t.name, j)));
        return;
      }
  if (t.values[0] != t.first || t.values[size - 1] != t.last) {
    out.push_back(make_finding(msg::lut_ends_mismatch,
                               at + " runs from " + std::to_string(t.values[0]) + " to " +
                                   std::to_string(t.values[size - 1]) + ", the other table's domain is [" +
                                   std::to_string(t.first) + ", " + std::to_string(t.last) + "]",
                               where));
    return;
  }
  for (uint32_t j = 0; j + 1 < size; ++j)
    if (t.values[j + 1] < t.values[j]) {
      out.push_back(make_finding(msg::lut_not_monotone,
                                 at + ": sample " + std::to_string(j + 1) + " (" + std::to_string(t.values[j + 1]) +
                                     ") < sample " + std::to_string(j) + " (" + std::to_string(t.values[j]) + ")",
                                 at_index(t.name, j + 1)));
      return;
    }
  for (uint32_t j = 0; j + 1 < size; ++j)
    if (t.slopes[j] < 0.0f) {
      out.push_back(make_finding(msg::lut_negative_slope,
                                 std::string(kLutChannelNames[channel]) + " " + t.slope_name + " entry " +
                                     std::to_string(j) + " is " + std::to_string(t.slopes[j]),
                                 at_index(t.slope_name, j)));
      return;
    }
  for (uint32_t j = 0; j + 1 < size; ++j) {
    const double exact = lut_interval_slope(t.lo, t.hi, size, t.values[j], t.values[j + 1]);
    if (std::abs(double(t.slopes[j]) - exact) > kSlopeRelativeTolerance * std::abs(exact) + kSlopeAbsoluteTolerance) {
      out.push_back(make_finding(msg::lut_slope_mismatch,
                                 std::string(kLutChannelNames[channel]) + " " + t.slope_name + " entry " +
                                     std::to_string(j) + " is " + std::to_string(t.slopes[j]) +
                                     ", the interpolant's slope is " + std::to_string(exact),
                                 at_index(t.slope_name, j)));
      return;
    }
  }
}

void check_lut(const Asset& a, std::vector<Finding>& out) {
  const auto& params = a.metadata()["parameters"];
  if (!params.is_object() || !params.contains("size") || !params["size"].is_number_unsigned() ||
      params["size"].get<uint64_t>() < kLutMinSize || params["size"].get<uint64_t>() > kLutMaxSize) {
    out.push_back(make_finding(msg::lut_bad_parameters, "parameters.size must be an integer in 2..65536",
                               {{"key", "parameters.size"}}));
    return;
  }
  const uint32_t size = params["size"].get<uint32_t>();
  const std::pair<std::string_view, uint64_t> shapes[] = {{kLutDomainsSection, kLutDomainValues},
                                                          {kLutForwardSection, size},
                                                          {kLutForwardSlopeSection, size - 1},
                                                          {kLutInverseSection, size},
                                                          {kLutInverseSlopeSection, size - 1}};
  for (const auto& [name, length] : shapes) {
    const SectionInfo& s = a.section(std::string(name));
    if (s.shape != std::vector<uint64_t>{kLutChannels, length}) {
      out.push_back(make_finding(msg::lut_section_shape,
                                 "'" + std::string(name) + "' should be f32 [2, " + std::to_string(length) + "]",
                                 {{"section", name}}));
      return;
    }
  }
  std::vector<std::vector<float>> data;
  for (const auto& [name, length] : shapes) {
    data.push_back(a.read<float>(std::string(name)));
    for (size_t i = 0; i < data.back().size(); ++i)
      if (!std::isfinite(data.back()[i])) {
        out.push_back(make_finding(msg::lut_non_finite,
                                   "'" + std::string(name) + "' channel " + std::to_string(i / length) + " entry " +
                                       std::to_string(i % length),
                                   {{"section", name}, {"index", i}}));
        return;
      }
  }
  const std::vector<float>&domains = data[0], &forward = data[1], &forward_slope = data[2], &inverse = data[3],
        &inverse_slope = data[4];
  const size_t findings_before = out.size();
  for (uint32_t c = 0; c < kLutChannels; ++c) {
    const float* d = &domains[size_t(c) * kLutDomainValues];
    const size_t row = size_t(c) * size, slope_row = size_t(c) * (size - 1);
    const Table tables[] = {
        {"forward", "forward_slope", d[0], d[1], d[2], d[3], &forward[row], &forward_slope[slope_row]},
        {"inverse", "inverse_slope", d[2], d[3], d[0], d[1], &inverse[row], &inverse_slope[slope_row]}};
    for (const Table& t : tables) {
      check_table(t, size, c, out);
      if (out.size() > findings_before) return;
    }
  }
}

}  // namespace

AssetKind lut_kind() {
  AssetKind k;
  k.id = kLutKindId;
  k.name = "lut";
  k.summary = "standardization LUTs of glints: G and G^-1 per normal component with their slope tables";
  for (std::string_view name :
       {kLutDomainsSection, kLutForwardSection, kLutForwardSlopeSection, kLutInverseSection, kLutInverseSlopeSection})
    k.required_sections.push_back({std::string(name), {ElementType::f32}, 2});
  k.knows_section = [](const std::string& name) {
    return name == kLutDomainsSection || name == kLutForwardSection || name == kLutForwardSlopeSection ||
           name == kLutInverseSection || name == kLutInverseSlopeSection;
  };
  k.check_invariants = check_lut;
  return k;
}

}  // namespace mbk
