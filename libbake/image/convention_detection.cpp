// The curl statistic of a normal map's two green-channel readings (see convention_detection.h).
#include "libbake/image/convention_detection.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "libbake/core/parallel.h"

namespace mbk {
namespace {

struct RowSums {
  double ab = 0.0, w = 0.0, w2 = 0.0;
  uint64_t stencils = 0;
};

}  // namespace

double ConventionEvidence::required_confidence() const {
  // n_eff is at least 1 wherever there is curl energy; 0 (no stencil, or none with energy) asks as much as 1.
  return std::max(kConventionMinConfidence, kConventionNullSigmas / std::sqrt(std::max(1.0, effective_stencils)));
}

std::optional<YConvention> ConventionEvidence::verdict() const {
  if (std::abs(statistic) < required_confidence()) return std::nullopt;
  return statistic > 0.0 ? YConvention::plus_y : YConvention::minus_y;
}

nlohmann::json ConventionEvidence::to_json() const {
  return {{"statistic", statistic},
          {"confidence", std::abs(statistic)},
          {"required_confidence", required_confidence()},
          {"effective_stencils", effective_stencils},
          {"stencils", stencils}};
}

ConventionEvidence measure_convention(const NormalMap& map) {
  ConventionEvidence e;
  const uint32_t W = map.width, H = map.height;
  if (W < 3 || H < 3) return e;
  std::vector<RowSums> rows(H);
  parallel_for(1, H - 1, [&](int64_t r) {
    const uint32_t row = uint32_t(r);
    RowSums& s = rows[row];
    for (uint32_t x = 1; x + 1 < W; ++x) {
      const Vec3f &left = map.at(x - 1, row), &right = map.at(x + 1, row);
      const Vec3f &up = map.at(x, row - 1), &down = map.at(x, row + 1);
      if (std::min({left.z(), right.z(), up.z(), down.z()}) < kConventionMinZ) continue;
      // a = dq/dx, b = dp/dy (y up), each times 2: the factor cancels in s and n_eff.
      const double a = -double(right.y()) / right.z() + double(left.y()) / left.z();
      const double b = -double(up.x()) / up.z() + double(down.x()) / down.z();
      const double w = a * a + b * b;
      s.ab += a * b;
      s.w += w;
      s.w2 += w * w;
      ++s.stencils;
    }
  });
  RowSums total;
  for (const RowSums& s : rows) {
    total.ab += s.ab;
    total.w += s.w;
    total.w2 += s.w2;
    total.stencils += s.stencils;
  }
  e.stencils = total.stencils;
  if (total.w > 0.0) {
    e.statistic = 2.0 * total.ab / total.w;
    e.effective_stencils = total.w * total.w / total.w2;
  }
  return e;
}

}  // namespace mbk
