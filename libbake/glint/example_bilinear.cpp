// Bilinear, border-clipped reading of the example with its exact derivative: see example_bilinear.h.
#include "libbake/glint/example_bilinear.h"

#include <algorithm>
#include <cmath>

namespace mbk {

ExampleChannels normal_components(const NormalMap& example) {
  ExampleChannels out{example.width, example.height, {}};
  out.texels.reserve(example.texels.size());
  for (const Vec3f& t : example.texels) out.texels.emplace_back(t.x(), t.y());
  return out;
}

NormalSample sample_example_bilinear(const ExampleChannels& example, const Vec2& e) {
  const double t0 = e.x() - 0.5, t1 = e.y() - 0.5;
  const double c0 = std::floor(t0), c1 = std::floor(t1);
  const double f0 = t0 - c0, f1 = t1 - c1;
  const auto clamp_index = [](double v, uint32_t n) { return uint32_t(std::clamp(v, 0.0, double(n - 1))); };
  const uint32_t x0 = clamp_index(c0, example.width), x1 = clamp_index(c0 + 1, example.width);
  const uint32_t r0 = clamp_index(c1, example.height), r1 = clamp_index(c1 + 1, example.height);
  const auto n2 = [&](uint32_t x, uint32_t r) { return example.texels[size_t(r) * example.width + x]; };
  const Vec2 n00 = n2(x0, r0), n10 = n2(x1, r0), n01 = n2(x0, r1), n11 = n2(x1, r1);
  NormalSample s;
  s.n = (1 - f0) * (1 - f1) * n00 + f0 * (1 - f1) * n10 + (1 - f0) * f1 * n01 + f0 * f1 * n11;
  s.jacobian.col(0) = (1 - f1) * (n10 - n00) + f1 * (n11 - n01);
  s.jacobian.col(1) = (1 - f0) * (n01 - n00) + f0 * (n11 - n10);
  return s;
}

}  // namespace mbk
