// Asset kind 4, `sh`: the SH NDF pyramid of a normal map ([Han07] Sec. 7.4). Sections `normals` f32 [H, W, 3]
// (level 0, whose coefficients are Y_lm(n)), `level_1` .. `level_{K-1}` f16 or f32 [h, w, (L+1)^2] holding
// g_lm = the area-weighted mean of Y_lm over the finest normals each texel covers, and `window` f32 [L + 1].
// formats/SPEC.md, "Kind 4: sh". The checks use only properties of means of the basis, so they need no SH
// code: g_00 = Y_00 = 1 / (2 sqrt(pi)); |g_lm| <= max |Y_lm|; and band 1 is linear in n
// ((Y1-1, Y10, Y11) = sqrt(3 / (4 pi)) (y, z, x)), so g_1m is c1 times the MIP mean of the normals.
#include <cmath>
#include <numbers>
#include <optional>

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

// The parameters every check needs; nullopt (with finding 14001) when they are missing or out of range.
struct ShParameters {
  std::vector<LevelSize> sizes;   // width, height and levels read as every pyramid kind reads them
  uint64_t order = 0, count = 0;  // L and (L+1)^2
  std::string precision;
  ElementType type = ElementType::f16;
  Tolerance tol{0, 0};
};

std::optional<ShParameters> read_sh_parameters(const nlohmann::json& p, std::vector<Finding>& out) {
  ShParameters sp;
  if (std::string problem = parse_mip_parameters(p, sp.sizes); !problem.empty()) {
    out.push_back(make_finding(msg::sh_bad_parameters, problem));
    return std::nullopt;
  }
  if (!p.contains("order") || !p["order"].is_number_unsigned() || !p.contains("precision") ||
      !p["precision"].is_string() || !p.contains("window") || !p["window"].is_string()) {
    out.push_back(make_finding(msg::sh_bad_parameters, "order, precision or window missing"));
    return std::nullopt;
  }
  sp.order = p["order"].get<uint64_t>();
  sp.precision = p["precision"].get<std::string>();
  if (sp.order > kMaxOrder || (sp.precision != "f16" && sp.precision != "f32")) {
    out.push_back(make_finding(msg::sh_bad_parameters, "order above 256 or precision not f16/f32"));
    return std::nullopt;
  }
  sp.count = (sp.order + 1) * (sp.order + 1);
  sp.type = sp.precision == "f16" ? ElementType::f16 : ElementType::f32;
  sp.tol = sp.type == ElementType::f16 ? Tolerance{1.0 / 2048, 1e-4} : Tolerance{1e-6, 2e-6};
  return sp;
}

// Every section's type and shape (14002); false after the first that differs.
bool check_sh_shapes(const Asset& a, const ShParameters& sp, std::vector<Finding>& out) {
  const uint32_t W = sp.sizes[0].width, H = sp.sizes[0].height;
  auto shape_finding = [&](const std::string& name, const std::string& want) {
    out.push_back(make_finding(msg::sh_section_shape, "'" + name + "' should be " + want));
    return false;
  };
  const SectionInfo* n = a.find("normals");
  if (!n || n->type != ElementType::f32 || n->shape != std::vector<uint64_t>{H, W, 3})
    return shape_finding("normals", "f32 [" + number_text(H) + ", " + number_text(W) + ", 3]");
  const SectionInfo* win = a.find("window");
  if (!win || win->type != ElementType::f32 || win->shape != std::vector<uint64_t>{sp.order + 1})
    return shape_finding("window", "f32 [" + number_text(sp.order + 1) + "]");
  for (size_t k = 1; k < sp.sizes.size(); ++k) {
    const SectionInfo* s = a.find(level_name(k));
    if (!s || s->type != sp.type || s->shape != std::vector<uint64_t>{sp.sizes[k].height, sp.sizes[k].width, sp.count})
      return shape_finding(level_name(k), sp.precision + " [" + number_text(sp.sizes[k].height) + ", " +
                                              number_text(sp.sizes[k].width) + ", " + number_text(sp.count) + "]");
  }
  if (a.find(level_name(sp.sizes.size())))
    return shape_finding(level_name(sp.sizes.size()), "absent: a " + number_text(W) + "x" + number_text(H) +
                                                          " image has " + number_text(sp.sizes.size()) + " levels");
  return true;
}

// Finite values (14003), then the window (14008), then unit finest normals (14004).
bool check_sh_values(const std::vector<float>& normals, const std::vector<float>& window,
                     const std::vector<std::vector<float>>& levels, std::vector<Finding>& out) {
  auto non_finite = [&](const std::vector<float>& v, const std::string& name) {
    for (size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i])) {
        out.push_back(make_finding(msg::sh_non_finite, name + " element " + number_text(i)));
        return true;
      }
    return false;
  };
  if (non_finite(normals, "normals") || non_finite(window, "window")) return false;
  for (size_t k = 1; k < levels.size(); ++k)
    if (non_finite(levels[k], level_name(k))) return false;
  for (size_t i = 0; i < window.size(); ++i)
    if ((i == 0 && window[i] != 1.0f) || !(window[i] > 0.0f && window[i] <= 1.0f) ||
        (i > 0 && window[i] > window[i - 1])) {
      out.push_back(make_finding(msg::sh_bad_window, "window[" + number_text(i) + "] = " + number_text(window[i])));
      return false;
    }
  for (size_t t = 0; t < normals.size() / 3; ++t) {
    const float* v = &normals[3 * t];
    const double len = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
    if (std::abs(len - 1.0) > kUnitTolerance) {
      out.push_back(make_finding(msg::sh_normal_not_unit, "normal " + number_text(t) + ": length " + number_text(len)));
      return false;
    }
  }
  return true;
}

// One texel's coefficients c: g_00 (14005), every |g_lm| within its bound (14006), band 1 = c1 times the mean of
// the finest normals it covers, `mean` (14007). `at` names the texel.
bool check_sh_texel(const float* c, const double mean[3], const ShParameters& sp, const std::string& at,
                    std::vector<Finding>& out) {
  const double y00 = 0.5 / std::sqrt(std::numbers::pi), c1 = std::sqrt(3.0 / (4.0 * std::numbers::pi));
  if (std::abs(c[0] - y00) > sp.tol.at(y00)) {
    out.push_back(make_finding(msg::sh_dc_wrong, at + ": g_00 = " + number_text(c[0])));
    return false;
  }
  for (uint32_t l = 0; l <= sp.order; ++l)
    for (int m = -int(l); m <= int(l); ++m) {
      const double bound = std::sqrt((2.0 * l + 1.0) / ((m == 0 ? 4.0 : 2.0) * std::numbers::pi));
      const float v = c[l * (l + 1) + uint32_t(m + int(l)) - l];
      if (std::abs(v) > bound + sp.tol.at(bound)) {
        out.push_back(make_finding(msg::sh_coefficient_out_of_bounds,
                                   at + ": g_" + number_text(l) + "," + number_text(m) + " = " + number_text(v)));
        return false;
      }
    }
  if (sp.order < 1) return true;
  const double expected[3] = {c1 * mean[1], c1 * mean[2], c1 * mean[0]};  // (Y1-1, Y10, Y11) ~ (y, z, x)
  for (int i = 0; i < 3; ++i)
    if (std::abs(c[1 + i] - expected[i]) > sp.tol.at(c1)) {
      out.push_back(make_finding(msg::sh_band1_not_mean_normal, at + ": g_1," + number_text(i - 1) + " = " +
                                                                    number_text(c[1 + i]) + ", normals give " +
                                                                    number_text(expected[i])));
      return false;
    }
  return true;
}

void check_sh(const Asset& a, std::vector<Finding>& out) {
  const std::optional<ShParameters> sp = read_sh_parameters(a.metadata()["parameters"], out);
  if (!sp || !check_sh_shapes(a, *sp, out)) return;
  const std::vector<float> normals = a.read<float>("normals"), window = a.read<float>("window");
  std::vector<std::vector<float>> levels(1);
  for (size_t k = 1; k < sp->sizes.size(); ++k) levels.push_back(a.read_as_float(level_name(k)));
  if (!check_sh_values(normals, window, levels, out)) return;
  const uint32_t W = sp->sizes[0].width, H = sp->sizes[0].height;
  for (size_t k = 1; k < levels.size(); ++k) {
    const uint32_t w = sp->sizes[k].width, h = sp->sizes[k].height;
    const auto wx = mip_texel_weights(w, W), wy = mip_texel_weights(h, H);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        double mean[3] = {0, 0, 0};
        for (const MipWeight& fy : wy[y])
          for (const MipWeight& fx : wx[x])
            for (int i = 0; i < 3; ++i)
              mean[i] += fy.weight * fx.weight * normals[(size_t(fy.index) * W + fx.index) * 3 + i];
        const std::string at = level_name(k) + " texel (" + number_text(x) + ", " + number_text(y) + ")";
        if (!check_sh_texel(&levels[k][(size_t(y) * w + x) * sp->count], mean, *sp, at, out)) return;
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
