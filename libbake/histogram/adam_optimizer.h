// Adam ([KB14], Kingma & Ba 2014, Algorithm 1) over a flat array of f32 parameters: the optimiser [Shah24] Sec. 5
// trains the neural histogram's weights and features with. Element by element in index order, so deterministic.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace mbk {

class AdamOptimizer {
 public:
  explicit AdamOptimizer(size_t parameters) : m_(parameters), v_(parameters) {}
  // One step of the parameters against `gradient` (the same length) with step size `learning_rate` (alpha).
  void step(std::span<float> parameters, std::span<const float> gradient, double learning_rate);

 private:
  std::vector<float> m_, v_;  // first and second moment estimates
  uint64_t steps_ = 0;
};

}  // namespace mbk
