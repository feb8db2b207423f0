// Asset kind 10, `lut`: the standardization transform of an example normal map for histogram-preserving blending
// ([Wang20] Eq. 6, [Heitz18] Sec. 3) as knots (x_i, z_i) per channel n_x, n_y (formats/lut_layout.h).
// formats/SPEC.md, "Kind 10: lut".
//
// Invariants `validate` checks, in this order (the first finding ends the check): parameters (12002), section
// shapes (12003), finite values (12001), then per channel: a one-knot (constant) channel has z = 0 (12004);
// x and z strictly increasing (12005), so that the forward and inverse interpolants are each other's inverse.
#include <cmath>
#include <string>

#include "formats/number_text.h"
#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/lut_layout.h"

namespace mbk {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

void check_channel(const std::vector<float>& rows, uint32_t channel, std::vector<Finding>& out) {
  const std::string name(kLutKnotSections[channel]);
  const size_t M = rows.size() / kLutKnotColumns;
  if (M == 1 && rows[1] != 0.0f) {
    out.push_back(make_finding(msg::lut_bad_domain,
                               name + ": a one-knot (constant) channel must have z = 0, not " + number(rows[1]),
                               {{"section", name}, {"index", 0}}));
    return;
  }
  for (size_t i = 1; i < M; ++i)
    for (uint32_t col = 0; col < kLutKnotColumns; ++col)
      if (!(rows[2 * i + col] > rows[2 * (i - 1) + col])) {
        const char* axis = col == 0 ? "x" : "z";
        out.push_back(make_finding(msg::lut_not_monotone,
                                   name + ": knot " + number_text(i) + " has " + axis + " = " +
                                       number(rows[2 * i + col]) + ", not above knot " + number_text(i - 1) + "'s " +
                                       number(rows[2 * (i - 1) + col]),
                                   {{"section", name}, {"index", i}}));
        return;
      }
}

void check_lut(const Asset& a, std::vector<Finding>& out) {
  const std::optional<uint32_t> parameter = lut_size_parameter(a.metadata());
  if (!parameter) {
    out.push_back(make_finding(msg::lut_bad_parameters, "parameters.size must be an integer in 2..65536",
                               {{"key", "parameters.size"}}));
    return;
  }
  const uint32_t size = *parameter;
  for (std::string_view section : kLutKnotSections) {
    if (!lut_knot_shape_ok(a.section(std::string(section)).shape, size)) {
      out.push_back(make_finding(msg::lut_section_shape,
                                 "'" + std::string(section) + "' should be f32 [M, 2] with 1 <= M <= " +
                                     number_text(lut_max_knots(size)) + " (3 x size)",
                                 {{"section", section}}));
      return;
    }
  }
  for (uint32_t c = 0; c < kLutChannels; ++c) {
    const std::string name(kLutKnotSections[c]);
    const std::vector<float> rows = a.read<float>(name);
    for (size_t i = 0; i < rows.size(); ++i)
      if (!std::isfinite(rows[i])) {
        out.push_back(make_finding(msg::lut_non_finite,
                                   "'" + name + "' knot " + number_text(i / 2) + (i % 2 ? " z" : " x"),
                                   {{"section", name}, {"index", i / 2}}));
        return;
      }
    const size_t before = out.size();
    check_channel(rows, c, out);
    if (out.size() > before) return;
  }
}

}  // namespace

AssetKind lut_kind() {
  AssetKind k;
  k.id = kLutKindId;
  k.name = "lut";
  k.summary = "standardization transform of glints: knots (x, G(x)) per normal component, read forward and back";
  for (std::string_view name : kLutKnotSections)
    k.required_sections.push_back({std::string(name), {ElementType::f32}, 2});
  k.knows_section = [](const std::string& name) { return name == kLutKnotSections[0] || name == kLutKnotSections[1]; };
  k.check_invariants = check_lut;
  return k;
}

}  // namespace mbk
