// One Adam step (see adam_optimizer.h).
#include "libbake/histogram/adam_optimizer.h"

#include <cmath>

namespace mbk {

void AdamOptimizer::step(std::span<float> parameters, std::span<const float> gradient, double learning_rate) {
  constexpr double kBeta1 = 0.9, kBeta2 = 0.999;
  constexpr float kEpsilon = 1e-8f;
  ++steps_;
  // The bias corrections folded into the step size (Algorithm 1's last line, as [KB14] Sec. 2 suggests).
  const float rate = float(learning_rate * std::sqrt(1.0 - std::pow(kBeta2, double(steps_))) /
                           (1.0 - std::pow(kBeta1, double(steps_))));
  for (size_t i = 0; i < parameters.size(); ++i) {
    m_[i] = float(kBeta1) * m_[i] + float(1.0 - kBeta1) * gradient[i];
    v_[i] = float(kBeta2) * v_[i] + float(1.0 - kBeta2) * gradient[i] * gradient[i];
    parameters[i] -= rate * m_[i] / (std::sqrt(v_[i]) + kEpsilon);
  }
}

}  // namespace mbk
