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

LoopGains loop_gains_of_stacks(const float* stacks, uint32_t exemplars, uint32_t levels, uint32_t m, uint32_t channels) {
  std::vector<double> contrast(size_t(exemplars) * levels);
  for (uint32_t i = 0; i < exemplars; ++i)
    for (uint32_t k = 0; k < levels; ++k)
      contrast[size_t(i) * levels + k] = neighbourhood_contrast(stacks + (size_t(i) * levels + k) * m * m * channels,
                                                                m, channels, 1u << (levels - 1 - k));
  return LoopGains(levels, std::move(contrast));
}

double LoopGains::gain(uint32_t source_exemplar, uint32_t k, uint32_t destination_exemplar, uint32_t l) const {
  if (source_exemplar != destination_exemplar || l >= k) return 1.0;
  const double s = contrast_[size_t(source_exemplar) * levels_ + k], d = contrast_[size_t(source_exemplar) * levels_ + l];
  return s > 0.0 && d > 0.0 ? std::sqrt(s / d) : 1.0;
}

void apply_loop_gain(float* neighbourhood, uint32_t channels, double gain) {
  for (uint32_t c = 0; c < channels; ++c) {
    double mean = 0.0;
    for (uint32_t j = 0; j < 25; ++j) mean += neighbourhood[j * channels + c];
    mean /= 25.0;
    for (uint32_t j = 0; j < 25; ++j)
      neighbourhood[j * channels + c] = float(mean + gain * (neighbourhood[j * channels + c] - mean));
  }
}

}  // namespace mbk
