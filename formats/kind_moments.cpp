// Asset kind 8, `moments`: the MIP pyramid of the first two moments (about a shift) of a driver f, so that the mean
// and variance of f over a footprint come from two lookups ([Heitz13] Sec. 4.2; formats/moments_layout.h).
// formats/SPEC.md, "Kind 8: moments".
//
// Invariants `validate` checks, in this order (the first finding ends the check): parameters (18002), level
// shapes (18003), finite values (18001), level 0 second moment = first squared (18004), every texel's second
// moment >= its first squared (Jensen; 18005), every coarser texel the area-weighted mean of level 0 over its
// rectangle (18006).
#include <algorithm>
#include <cmath>
#include <limits>

#include "formats/number_text.h"
#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/mip_levels.h"
#include "formats/moments_layout.h"
#include "formats/pyramid_levels.h"

namespace mbk {
namespace {

// Float storage of a double value: half an ulp, 2^-24 relative. Allow 2^-22 of the scale, plus the smallest
// subnormal for values that round into float's subnormal range.
constexpr double kRelative = 0x1p-22;
constexpr double kAbsolute = std::numeric_limits<float>::denorm_min();

void check_moments(const Asset& a, std::vector<Finding>& out) {
  const auto& p = a.metadata()["parameters"];
  std::vector<LevelSize> sizes;  // width, height and levels read as every pyramid kind reads them
  if (std::string problem = parse_mip_parameters(p, sizes); !problem.empty()) {
    out.push_back(make_finding(msg::moments_bad_parameters, problem));
    return;
  }
  if (!p.contains("shift") || !p["shift"].is_number() || !std::isfinite(p["shift"].get<double>())) {
    out.push_back(make_finding(msg::moments_bad_parameters, "parameters.shift missing or not finite"));
    return;
  }
  const auto read =
      read_pyramid_levels(a, sizes, kMomentsChannels, msg::moments_level_shape, msg::moments_non_finite, out);
  if (!read) return;
  const std::vector<std::vector<float>>& levels = *read;
  const std::vector<float>& finest = levels[0];
  double scale[2] = {0.0, 0.0};
  for (size_t i = 0; i < finest.size(); ++i) scale[i % 2] = std::max(scale[i % 2], std::abs(double(finest[i])));
  const uint32_t W = sizes[0].width, H = sizes[0].height;
  for (size_t i = 0; i < finest.size(); i += 2) {
    const double d = finest[i], square = d * d;
    if (std::abs(double(finest[i + 1]) - square) > kRelative * square + kAbsolute) {
      out.push_back(make_finding(
          msg::moments_level0_not_square,
          "level_0 texel " + number_text(i / 2) + ": " + number_text(finest[i + 1]) + " vs " + number_text(square),
          {{"section", "level_0"}, {"texel", i / 2}}));
      return;
    }
  }
  for (size_t k = 0; k < levels.size(); ++k) {
    const auto& L = levels[k];
    const auto wx = mip_texel_weights(sizes[k].width, W), wy = mip_texel_weights(sizes[k].height, H);
    for (uint32_t y = 0; y < sizes[k].height; ++y)
      for (uint32_t x = 0; x < sizes[k].width; ++x) {
        const float* m = &L[(size_t(y) * sizes[k].width + x) * 2];
        const std::string at = moments_level_name(k) + " texel (" + number_text(x) + ", " + number_text(y) + ")";
        const nlohmann::json where = {{"section", moments_level_name(k)}, {"x", x}, {"row", y}};
        const double first_squared = double(m[0]) * m[0];
        if (double(m[1]) < first_squared - (kRelative * (first_squared + m[1]) + kAbsolute)) {
          out.push_back(make_finding(msg::moments_negative_variance,
                                     at + ": E[d^2] " + number_text(m[1]) + " < E[d]^2 " + number_text(first_squared),
                                     where));
          return;
        }
        if (k == 0) continue;
        const std::vector<double> mean = level0_mean(finest, W, kMomentsChannels, wx[x], wy[y]);
        for (int c = 0; c < 2; ++c)
          if (std::abs(mean[c] - m[c]) > kRelative * scale[c] + kAbsolute) {
            out.push_back(make_finding(msg::moments_parent_not_mean,
                                       at + ": moment " + number_text(c + 1) + " is " + number_text(m[c]) +
                                           ", level 0 gives " + number_text(mean[c]),
                                       where));
            return;
          }
      }
  }
}

}  // namespace

AssetKind moments_kind() {
  AssetKind k;
  k.id = kMomentsKindId;
  k.name = "moments";
  k.summary = "MIP pyramid of the first two moments (f, f^2, about a shift) of a driver image";
  k.required_sections = {{"level_0", {ElementType::f32}, 3}};
  k.knows_section = is_level_section_name;
  k.check_invariants = check_moments;
  return k;
}

}  // namespace mbk
