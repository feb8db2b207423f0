// Asset kind 1, `mip`: the MIP pyramid of a normal map, the baseline every filtering technique is compared
// with (and the input of Toksvig-style roughening, whose lengths it keeps). Sections level_0 .. level_{L-1},
// each f32 [height, width, 3]: level 0 holds the unit normals, level k the unnormalised area-weighted mean of
// the finest normals over each texel's rectangle (formats/mip_levels.h). formats/SPEC.md, "Kind 1: mip".
#include <cmath>

#include "formats/number_text.h"
#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/mip_levels.h"
#include "formats/pyramid_levels.h"

namespace mbk {
namespace {

std::string level_name(size_t k) { return "level_" + number_text(k); }

// Tolerances: level 0 is renormalised in float (|n| - 1 within a few ulps); coarser levels are means of
// level 0 accumulated in double and stored in float, so a texel matches the mean recomputed here from the
// stored level 0 to float rounding.
constexpr double kUnitTolerance = 1e-5;
constexpr double kMeanTolerance = 2e-6;

void check_mip(const Asset& a, std::vector<Finding>& out) {
  std::vector<LevelSize> sizes;
  if (std::string problem = parse_mip_parameters(a.metadata()["parameters"], sizes); !problem.empty()) {
    out.push_back(make_finding(msg::mip_bad_parameters, problem));
    return;
  }
  const auto read = read_pyramid_levels(a, sizes, 3, msg::mip_level_shape, msg::mip_non_finite, out);
  if (!read) return;
  const std::vector<std::vector<float>>& levels = *read;
  const uint32_t W = sizes[0].width, H = sizes[0].height;
  const std::vector<float>& finest = levels[0];
  for (size_t k = 0; k < levels.size(); ++k) {
    const auto& L = levels[k];
    const auto wx = mip_texel_weights(sizes[k].width, W), wy = mip_texel_weights(sizes[k].height, H);
    for (uint32_t y = 0; y < sizes[k].height; ++y)
      for (uint32_t x = 0; x < sizes[k].width; ++x) {
        const float* n = &L[(size_t(y) * sizes[k].width + x) * 3];
        const double len = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
        const std::string at = level_name(k) + " texel (" + number_text(x) + ", " + number_text(y) + ")";
        if (k == 0 && std::abs(len - 1.0) > kUnitTolerance) {
          out.push_back(make_finding(msg::mip_level0_not_unit, at + ": length " + number_text(len)));
          return;
        }
        if (len > 1.0 + kUnitTolerance) {
          out.push_back(make_finding(msg::mip_length_exceeds_one, at + ": length " + number_text(len)));
          return;
        }
        if (k == 0) continue;
        // The texel is the area-weighted mean of level 0 over its rectangle.
        const std::vector<double> mean = level0_mean(finest, W, 3, wx[x], wy[y]);
        for (int c = 0; c < 3; ++c)
          if (std::abs(mean[c] - n[c]) > kMeanTolerance) {
            out.push_back(make_finding(msg::mip_parent_not_mean, at + ": channel " + number_text(c) + " is " +
                                                                     number_text(n[c]) + ", level 0 gives " +
                                                                     number_text(mean[c])));
            return;
          }
      }
  }
}

}  // namespace

AssetKind mip_kind() {
  AssetKind k;
  k.id = 1;
  k.name = "mip";
  k.summary = "MIP pyramid of a normal map (unnormalised mean normals per level)";
  k.required_sections = {{"level_0", {ElementType::f32}, 3}};
  k.knows_section = is_level_section_name;
  k.check_invariants = check_mip;
  return k;
}

}  // namespace mbk
