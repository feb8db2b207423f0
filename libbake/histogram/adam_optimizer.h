// Adam ([KB14], Kingma & Ba 2014, Algorithm 1) over a flat array of f32 parameters: the optimiser [Shah24] Sec. 5
// trains the neural histogram's weights and features with. Element by element in index order, so deterministic.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace mbk {

class AdamOptimizer {
 public:
  AdamOptimizer(size_t parameters, float learning_rate) : m_(parameters), v_(parameters), rate_(learning_rate) {}
  // One step of the parameters against `gradient` (the same length).
  void step(std::span<float> parameters, std::span<const float> gradient);

 private:
  std::vector<float> m_, v_;  // first and second moment estimates
  float rate_;
  uint64_t steps_ = 0;
};

}  // namespace mbk
