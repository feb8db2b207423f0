// D_KL(exact || predicted) (see histogram_kl.h).
#include "libbake/histogram/histogram_kl.h"

#include <algorithm>
#include <cmath>

namespace mbk {

double histogram_kl(std::span<const double> exact, std::span<const double> predicted) {
  double kl = 0.0;
  for (size_t b = 0; b < exact.size(); ++b)
    if (exact[b] > 0.0) kl += exact[b] * std::log(exact[b] / std::max(predicted[b], 1e-12));
  return kl;
}

}  // namespace mbk
