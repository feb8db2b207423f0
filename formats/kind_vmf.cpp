// Asset kind 5, `vmf`: vMF mixture MIP maps of a normal map ([Han07] Sec. 7.6). Sections `level_k` f32
// [h, w, J, 4] holding (alpha, alpha r) per lobe for k = 0..K-1, and optionally `features_k` f32 [h, w, J, F]
// (alpha y). formats/SPEC.md, "Kind 5: vmf". The checks need no EM: amplitudes are >= 0 and sum to 1 per
// texel; |r| <= 1 (a mean of unit vectors); level 0 is one lobe (1, n) per texel; and, for unaligned fits,
// EM's M-step makes sum_j alpha_j r_j = sum_i w_i n_i exactly, so a texel's first moment is the MIP mean of
// the finest normals (read back from level 0).
#include <cmath>
#include <optional>

#include "formats/number_text.h"
#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/mip_levels.h"

namespace mbk {
namespace {

constexpr double kSumTolerance = 1e-5, kLengthTolerance = 1e-5, kMomentTolerance = 2e-5;

// Records a finding; false, so that a check can end with `return report(...)`.
bool report(std::vector<Finding>& out, const MessageInfo& m, const std::string& specifics) {
  out.push_back(make_finding(m, specifics));
  return false;
}

struct VmfParameters {
  std::vector<LevelSize> sizes;  // width, height and levels read as every pyramid kind reads them
  uint64_t J = 0, F = 0;         // lobes, feature channels
  double align = 0.0;
};

// The parameters (15001); nullopt after a finding.
std::optional<VmfParameters> read_vmf_parameters(const nlohmann::json& p, std::vector<Finding>& out) {
  auto has = [&](const char* key, bool is_unsigned) {
    return p.is_object() && p.contains(key) && (is_unsigned ? p[key].is_number_unsigned() : p[key].is_number());
  };
  VmfParameters vp;
  if (std::string problem = parse_mip_parameters(p, vp.sizes); !problem.empty()) {
    out.push_back(make_finding(msg::vmf_bad_parameters, problem));
    return std::nullopt;
  }
  if (!has("lobes", true) || !has("feature_channels", true) || !has("kappa_max", false) || !has("align", false)) {
    out.push_back(make_finding(msg::vmf_bad_parameters, "lobes, feature_channels, kappa_max or align missing"));
    return std::nullopt;
  }
  vp.J = p["lobes"].get<uint64_t>(), vp.F = p["feature_channels"].get<uint64_t>();
  const double kappa_max = p["kappa_max"].get<double>();
  vp.align = p["align"].get<double>();
  if (vp.J < 1 || vp.J > 16 || vp.F > 4 || !(kappa_max > 0.0) || !(vp.align >= 0.0)) {
    out.push_back(make_finding(msg::vmf_bad_parameters,
                               "lobes outside 1..16, more than 4 feature channels, kappa_max <= 0 or align < 0"));
    return std::nullopt;
  }
  return vp;
}

// Reads every level (and its features) after checking its type and shape (15002), then that they are finite
// (15003); false after a finding.
bool read_vmf_levels(const Asset& a, const VmfParameters& vp, std::vector<std::vector<float>>& levels,
                     std::vector<std::vector<float>>& features, std::vector<Finding>& out) {
  const uint64_t J = vp.J, F = vp.F;
  for (size_t k = 0; k < vp.sizes.size(); ++k) {
    const std::string name = "level_" + number_text(k), fname = "features_" + number_text(k);
    const std::vector<uint64_t> shape = {vp.sizes[k].height, vp.sizes[k].width, J, 4};
    const SectionInfo* s = a.find(name);
    if (!s || s->type != ElementType::f32 || s->shape != shape) {
      out.push_back(make_finding(msg::vmf_section_shape, "'" + name + "' should be f32 [" + number_text(shape[0]) +
                                                             ", " + number_text(shape[1]) + ", " + number_text(J) +
                                                             ", 4]"));
      return false;
    }
    const SectionInfo* f = a.find(fname);
    if (F ? (!f || f->type != ElementType::f32 || f->shape != std::vector<uint64_t>{shape[0], shape[1], J, F})
          : f != nullptr) {
      out.push_back(
          make_finding(msg::vmf_section_shape, "'" + fname + "' should be " +
                                                   (F ? "f32 [h, w, " + number_text(J) + ", " + number_text(F) + "]"
                                                      : std::string("absent (feature_channels = 0)"))));
      return false;
    }
    levels.push_back(a.read<float>(name));
    if (F) features.push_back(a.read<float>(fname));
  }
  if (a.find("level_" + number_text(vp.sizes.size()))) {
    out.push_back(make_finding(msg::vmf_section_shape, "more levels than the image has"));
    return false;
  }
  for (size_t k = 0; k < levels.size(); ++k) {
    for (float v : levels[k])
      if (!std::isfinite(v)) return report(out, msg::vmf_non_finite, "level_" + number_text(k));
    if (F)
      for (float v : features[k])
        if (!std::isfinite(v)) return report(out, msg::vmf_non_finite, "features_" + number_text(k));
  }
  return true;
}

// One texel's J lobes (and their F features each, when F > 0) at level k: amplitudes >= 0 summing to 1 (15004),
// empty lobes all zero (15008), |r| <= 1 (15005), level 0 one lobe (1, n) (15006). Adds the texel's first
// moment sum_j alpha_j r_j to `moment`; false after a finding.
bool check_vmf_lobes(const float* lobes, const float* lobe_features, const VmfParameters& vp, size_t k,
                     const std::string& at, double moment[3], std::vector<Finding>& out) {
  double sum = 0.0;
  int live = 0;
  for (uint64_t j = 0; j < vp.J; ++j) {
    const float* l = lobes + 4 * j;
    const double length = std::sqrt(double(l[1]) * l[1] + double(l[2]) * l[2] + double(l[3]) * l[3]);
    if (l[0] < 0.0f)
      return report(out, msg::vmf_amplitudes_not_normalised,
                    at + ": lobe " + number_text(j) + " alpha " + number_text(l[0]));
    bool features_zero = true;
    for (uint64_t f = 0; f < vp.F; ++f) features_zero = features_zero && lobe_features[j * vp.F + f] == 0.0f;
    if (l[0] == 0.0f && (length != 0.0 || !features_zero))
      return report(out, msg::vmf_empty_lobe_not_zero, at + ": lobe " + number_text(j));
    if (length > l[0] * (1.0 + kLengthTolerance))
      return report(
          out, msg::vmf_mean_too_long,
          at + ": lobe " + number_text(j) + " |alpha r| " + number_text(length) + ", alpha " + number_text(l[0]));
    sum += l[0];
    live += l[0] > 0.0f;
    for (int c = 0; c < 3; ++c) moment[c] += l[1 + c];
    if (k == 0 && l[0] > 0.0f && (std::abs(l[0] - 1.0) > 1e-6 || std::abs(length - 1.0) > kLengthTolerance))
      return report(out, msg::vmf_finest_not_single_lobe,
                    at + ": lobe " + number_text(j) + " alpha " + number_text(l[0]) + ", |r| " + number_text(length));
  }
  if (k == 0 && live != 1)
    return report(out, msg::vmf_finest_not_single_lobe, at + ": " + number_text(live) + " lobes");
  if (std::abs(sum - 1.0) > kSumTolerance)
    return report(out, msg::vmf_amplitudes_not_normalised, at + ": sum " + number_text(sum));
  return true;
}

// Unaligned fits: the texel's first moment equals the MIP mean of the finest normals it covers, read back from
// level 0 (alpha 1, r = n) through the rows wy and columns wx it covers (15007).
bool check_vmf_moment(const double moment[3], const std::vector<float>& level0, const VmfParameters& vp,
                      const std::vector<MipWeight>& wy, const std::vector<MipWeight>& wx, const std::string& at,
                      std::vector<Finding>& out) {
  double mean[3] = {0, 0, 0};
  for (const MipWeight& fy : wy)
    for (const MipWeight& fx : wx) {
      const float* l0 = &level0[(size_t(fy.index) * vp.sizes[0].width + fx.index) * vp.J * 4];
      for (uint64_t j = 0; j < vp.J; ++j)
        for (int c = 0; c < 3; ++c) mean[c] += fy.weight * fx.weight * l0[4 * j + 1 + c];
    }
  for (int c = 0; c < 3; ++c)
    if (std::abs(moment[c] - mean[c]) > kMomentTolerance)
      return report(out, msg::vmf_moment_not_mean_normal,
                    at + ": component " + number_text(c) + " " + number_text(moment[c]) + ", normals give " +
                        number_text(mean[c]));
  return true;
}

void check_vmf(const Asset& a, std::vector<Finding>& out) {
  const std::optional<VmfParameters> vp = read_vmf_parameters(a.metadata()["parameters"], out);
  std::vector<std::vector<float>> levels, features;
  if (!vp || !read_vmf_levels(a, *vp, levels, features, out)) return;
  const uint32_t W = vp->sizes[0].width, H = vp->sizes[0].height;
  for (size_t k = 0; k < levels.size(); ++k) {
    const uint32_t w = vp->sizes[k].width, h = vp->sizes[k].height;
    const auto wx = mip_texel_weights(w, W), wy = mip_texel_weights(h, H);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        const size_t texel = size_t(y) * w + x;
        const std::string at = "level_" + number_text(k) + " texel (" + number_text(x) + ", " + number_text(y) + ")";
        const float* lobe_features = vp->F ? &features[k][texel * vp->J * vp->F] : nullptr;
        double moment[3] = {0, 0, 0};
        if (!check_vmf_lobes(&levels[k][texel * vp->J * 4], lobe_features, *vp, k, at, moment, out)) return;
        if (k > 0 && vp->align == 0.0 && !check_vmf_moment(moment, levels[0], *vp, wy[y], wx[x], at, out)) return;
      }
  }
}

}  // namespace

AssetKind vmf_kind() {
  AssetKind k;
  k.id = 5;
  k.name = "vmf";
  k.summary = "vMF mixture MIP maps of a normal map ((alpha, alpha r) per lobe per texel)";
  k.required_sections = {{"level_0", {ElementType::f32}, 4}};
  k.knows_section = [](const std::string& name) {
    for (const std::string prefix : {"level_", "features_"})
      if (name.rfind(prefix, 0) == 0 && name.size() > prefix.size())
        return name.find_first_not_of("0123456789", prefix.size()) == std::string::npos;
    return false;
  };
  k.check_invariants = check_vmf;
  return k;
}

}  // namespace mbk
