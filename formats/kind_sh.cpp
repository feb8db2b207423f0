// Asset kind 4, `sh`: the SH NDF pyramid of a normal map ([Han07] Sec. 7.4). Sections `normals` f32 [H, W, 3]
// (level 0, whose coefficients are Y_lm(n)), `level_1` .. `level_{K-1}` f16 or f32 [h, w, (L+1)^2] holding
// g_lm = the area-weighted mean of Y_lm over the finest normals each texel covers, and `window` f32 [L + 1].
// formats/SPEC.md, "Kind 4: sh". The checks use only properties of means of the basis, so they need no SH
// code: g_00 = Y_00 = 1 / (2 sqrt(pi)); |g_lm| <= max |Y_lm|; and band 1 is linear in n
// ((Y1-1, Y10, Y11) = sqrt(3 / (4 pi)) (y, z, x)), so g_1m is c1 times the MIP mean of the normals.
#include <cmath>
#include <numbers>

#include "formats/number_text.h"
#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/mip_levels.h"

namespace mbk {
namespace {

std::string level_name(size_t k) { return "level_" + number_text(k); }

constexpr double kUnitTolerance = 1e-5;
constexpr uint32_t kMaxOrder = 256;

struct Tolerance {
  double relative, absolute;  // f16: half a unit in the last place of an 11-bit significand; f32: accumulated rounding
  double at(double v) const { return relative * std::abs(v) + absolute; }
};

void check_sh(const Asset& a, std::vector<Finding>& out) {
  const auto& p = a.metadata()["parameters"];
  auto unsigned_key = [&](const char* key) { return p.is_object() && p.contains(key) && p[key].is_number_unsigned(); };
  std::vector<LevelSize> sizes;  // width, height and levels read as every pyramid kind reads them
  if (std::string problem = parse_mip_parameters(p, sizes); !problem.empty()) {
    out.push_back(make_finding(msg::sh_bad_parameters, problem));
    return;
  }
  if (!unsigned_key("order") || !p.contains("precision") || !p["precision"].is_string() || !p.contains("window") ||
      !p["window"].is_string()) {
    out.push_back(make_finding(msg::sh_bad_parameters, "order, precision or window missing"));
    return;
  }
  const uint64_t order = p["order"].get<uint64_t>();
  const std::string precision = p["precision"].get<std::string>();
  if (order > kMaxOrder || (precision != "f16" && precision != "f32")) {
    out.push_back(make_finding(msg::sh_bad_parameters, "order above 256 or precision not f16/f32"));
    return;
  }
  const uint64_t count = uint64_t(order + 1) * (order + 1);
  const ElementType type = precision == "f16" ? ElementType::f16 : ElementType::f32;
  const Tolerance tol = type == ElementType::f16 ? Tolerance{1.0 / 2048, 1e-4} : Tolerance{1e-6, 2e-6};
  const uint32_t W = sizes[0].width, H = sizes[0].height;
  auto shape_finding = [&](const std::string& name, const std::string& want) {
    out.push_back(make_finding(msg::sh_section_shape, "'" + name + "' should be " + want));
  };
  const SectionInfo* n = a.find("normals");
  if (!n || n->type != ElementType::f32 || n->shape != std::vector<uint64_t>{H, W, 3})
    return shape_finding("normals", "f32 [" + number_text(H) + ", " + number_text(W) + ", 3]");
  const SectionInfo* win = a.find("window");
  if (!win || win->type != ElementType::f32 || win->shape != std::vector<uint64_t>{order + 1})
    return shape_finding("window", "f32 [" + number_text(order + 1) + "]");
  for (size_t k = 1; k < sizes.size(); ++k) {
    const SectionInfo* s = a.find(level_name(k));
    if (!s || s->type != type || s->shape != std::vector<uint64_t>{sizes[k].height, sizes[k].width, count})
      return shape_finding(level_name(k), precision + " [" + number_text(sizes[k].height) + ", " +
                                              number_text(sizes[k].width) + ", " + number_text(count) + "]");
  }
  if (a.find(level_name(sizes.size())))
    return shape_finding(level_name(sizes.size()), "absent: a " + number_text(W) + "x" + number_text(H) +
                                                       " image has " + number_text(sizes.size()) + " levels");
  const std::vector<float> normals = a.read<float>("normals"), window = a.read<float>("window");
  std::vector<std::vector<float>> levels(1);
  for (size_t k = 1; k < sizes.size(); ++k) levels.push_back(a.read_as_float(level_name(k)));
  auto non_finite = [&](const std::vector<float>& v, const std::string& name) {
    for (size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i])) {
        out.push_back(make_finding(msg::sh_non_finite, name + " element " + number_text(i)));
        return true;
      }
    return false;
  };
  if (non_finite(normals, "normals") || non_finite(window, "window")) return;
  for (size_t k = 1; k < levels.size(); ++k)
    if (non_finite(levels[k], level_name(k))) return;
  for (size_t i = 0; i < window.size(); ++i)
    if ((i == 0 && window[i] != 1.0f) || !(window[i] > 0.0f && window[i] <= 1.0f) ||
        (i > 0 && window[i] > window[i - 1])) {
      out.push_back(make_finding(msg::sh_bad_window, "window[" + number_text(i) + "] = " + number_text(window[i])));
      return;
    }
  for (size_t t = 0; t < size_t(W) * H; ++t) {
    const float* v = &normals[3 * t];
    const double len = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
    if (std::abs(len - 1.0) > kUnitTolerance) {
      out.push_back(make_finding(msg::sh_normal_not_unit, "normal " + number_text(t) + ": length " + number_text(len)));
      return;
    }
  }
  const double y00 = 0.5 / std::sqrt(std::numbers::pi), c1 = std::sqrt(3.0 / (4.0 * std::numbers::pi));
  for (size_t k = 1; k < levels.size(); ++k) {
    const std::vector<float>& g = levels[k];
    const uint32_t w = sizes[k].width, h = sizes[k].height;
    const auto wx = mip_texel_weights(w, W), wy = mip_texel_weights(h, H);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        const float* c = &g[(size_t(y) * w + x) * count];
        const std::string at = level_name(k) + " texel (" + number_text(x) + ", " + number_text(y) + ")";
        if (std::abs(c[0] - y00) > tol.at(y00)) {
          out.push_back(make_finding(msg::sh_dc_wrong, at + ": g_00 = " + number_text(c[0])));
          return;
        }
        for (uint32_t l = 0; l <= order; ++l)
          for (int m = -int(l); m <= int(l); ++m) {
            const double bound = std::sqrt((2.0 * l + 1.0) / ((m == 0 ? 4.0 : 2.0) * std::numbers::pi));
            const float v = c[l * (l + 1) + uint32_t(m + int(l)) - l];
            if (std::abs(v) > bound + tol.at(bound)) {
              out.push_back(make_finding(msg::sh_coefficient_out_of_bounds,
                                         at + ": g_" + number_text(l) + "," + number_text(m) + " = " + number_text(v)));
              return;
            }
          }
        if (order < 1) continue;
        double mean[3] = {0, 0, 0};
        for (const MipWeight& fy : wy[y])
          for (const MipWeight& fx : wx[x])
            for (int i = 0; i < 3; ++i)
              mean[i] += fy.weight * fx.weight * normals[(size_t(fy.index) * W + fx.index) * 3 + i];
        const double expected[3] = {c1 * mean[1], c1 * mean[2], c1 * mean[0]};  // (Y1-1, Y10, Y11) ~ (y, z, x)
        for (int i = 0; i < 3; ++i)
          if (std::abs(c[1 + i] - expected[i]) > tol.at(c1)) {
            out.push_back(make_finding(msg::sh_band1_not_mean_normal, at + ": g_1," + number_text(i - 1) + " = " +
                                                                          number_text(c[1 + i]) + ", normals give " +
                                                                          number_text(expected[i])));
            return;
          }
      }
  }
}

}  // namespace

AssetKind sh_kind() {
  AssetKind k;
  k.id = 4;
  k.name = "sh";
  k.summary = "SH NDF pyramid of a normal map (mean of Y_lm over the normals under each MIP texel)";
  k.required_sections = {{"normals", {ElementType::f32}, 3}, {"window", {ElementType::f32}, 1}};
  k.knows_section = [](const std::string& name) {
    if (name == "normals" || name == "window") return true;
    if (name.rfind("level_", 0) != 0 || name.size() == 6) return false;
    return name.find_first_not_of("0123456789", 6) == std::string::npos;
  };
  k.check_invariants = check_sh;
  return k;
}

}  // namespace mbk
