// Reading pyramid levels for validation (see pyramid_levels.h).
#include "formats/pyramid_levels.h"

#include <cmath>
#include <string>

#include "formats/asset.h"

namespace mbk {

std::optional<std::vector<std::vector<float>>> read_pyramid_levels(const Asset& a, const std::vector<LevelSize>& sizes,
                                                                   uint64_t channels, const MessageInfo& shape,
                                                                   const MessageInfo& non_finite,
                                                                   std::vector<Finding>& out) {
  auto name = [](size_t k) { return "level_" + std::to_string(k); };
  std::vector<std::vector<float>> levels;
  for (size_t k = 0; k < sizes.size(); ++k) {
    const SectionInfo* s = a.find(name(k));
    if (!s || s->type != ElementType::f32 ||
        s->shape != std::vector<uint64_t>{sizes[k].height, sizes[k].width, channels}) {
      out.push_back(make_finding(shape,
                                 "'" + name(k) + "' should be f32 [" + std::to_string(sizes[k].height) + ", " +
                                     std::to_string(sizes[k].width) + ", " + std::to_string(channels) + "]",
                                 {{"section", name(k)}}));
      return std::nullopt;
    }
    levels.push_back(a.read<float>(name(k)));
  }
  if (a.find(name(sizes.size()))) {
    out.push_back(make_finding(
        shape,
        "more levels than a " + std::to_string(sizes[0].width) + "x" + std::to_string(sizes[0].height) + " image has",
        {{"section", name(sizes.size())}}));
    return std::nullopt;
  }
  for (size_t k = 0; k < levels.size(); ++k)
    for (size_t i = 0; i < levels[k].size(); ++i)
      if (!std::isfinite(levels[k][i])) {
        out.push_back(
            make_finding(non_finite, name(k) + " element " + std::to_string(i), {{"section", name(k)}, {"index", i}}));
        return std::nullopt;
      }
  return levels;
}

std::vector<double> level0_mean(const std::vector<float>& finest, uint32_t width, uint32_t channels,
                                const std::vector<MipWeight>& wx, const std::vector<MipWeight>& wy) {
  std::vector<double> mean(channels, 0.0);
  for (const MipWeight& fy : wy)
    for (const MipWeight& fx : wx) {
      const float* f = &finest[(size_t(fy.index) * width + fx.index) * channels];
      for (uint32_t c = 0; c < channels; ++c) mean[c] += fy.weight * fx.weight * f[c];
    }
  return mean;
}

}  // namespace mbk
