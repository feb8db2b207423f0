// Matching across a loop at equal contrast (see loop_transitions.h).
#include "libbake/synth/loop_transitions.h"

#include <algorithm>
#include <cmath>

namespace mbk {

double neighbourhood_contrast(const float* level, uint32_t m, uint32_t channels, uint32_t h) {
  constexpr int64_t r = 2;  // 5 x 5
  double total = 0.0;
  for (uint32_t y = 0; y < m; ++y)
    for (uint32_t x = 0; x < m; ++x)
      for (uint32_t c = 0; c < channels; ++c) {
        double sum = 0.0, sq = 0.0;
        for (int64_t dy = -r; dy <= r; ++dy)
          for (int64_t dx = -r; dx <= r; ++dx) {
            const int64_t sx = ((int64_t(x) + dx * h) % m + m) % m, sy = ((int64_t(y) + dy * h) % m + m) % m;
            const double v = level[(size_t(sy) * m + size_t(sx)) * channels + c];
            sum += v;
            sq += v * v;
          }
        total += std::max(0.0, sq / 25.0 - (sum / 25.0) * (sum / 25.0));
      }
  return total / (double(m) * m);
}

LoopContrast loop_contrast_of_stacks(const float* stacks, uint32_t exemplars, uint32_t levels, uint32_t m,
                                     uint32_t channels) {
  std::vector<double> contrast(size_t(exemplars) * levels);
  for (uint32_t i = 0; i < exemplars; ++i)
    for (uint32_t k = 0; k < levels; ++k)
      contrast[size_t(i) * levels + k] = neighbourhood_contrast(stacks + (size_t(i) * levels + k) * m * m * channels, m,
                                                                channels, 1u << (levels - 1 - k));
  return LoopContrast(levels, std::move(contrast));
}

void remove_neighbourhood_mean(float* neighbourhood, uint32_t channels) {
  double mean[4] = {0, 0, 0, 0};
  for (uint32_t j = 0; j < 25 * channels; ++j) mean[j % channels] += neighbourhood[j] / 25.0;
  for (uint32_t j = 0; j < 25 * channels; ++j) neighbourhood[j] = float(neighbourhood[j] - mean[j % channels]);
}

void bring_to_contrast(float* neighbourhood, uint32_t channels, double target) {
  if (target <= 0.0) return;
  double mean[4] = {0, 0, 0, 0}, variance = 0.0;
  for (uint32_t j = 0; j < 25 * channels; ++j) mean[j % channels] += neighbourhood[j] / 25.0;
  for (uint32_t j = 0; j < 25 * channels; ++j)
    variance += (neighbourhood[j] - mean[j % channels]) * (neighbourhood[j] - mean[j % channels]) / 25.0;
  if (variance <= 1e-6 * target) return;  // flat (to rounding): no shape to scale, and a gain above 1000 is noise
  const double scale = std::sqrt(target / variance);
  for (uint32_t j = 0; j < 25 * channels; ++j)
    neighbourhood[j] = float(mean[j % channels] + scale * (neighbourhood[j] - mean[j % channels]));
}

}  // namespace mbk
