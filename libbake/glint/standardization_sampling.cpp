// Knots of the standardization transform (see standardization_sampling.h).
#include "libbake/glint/standardization_sampling.h"

#include <algorithm>

#include "formats/error.h"
#include "formats/lut_layout.h"

namespace mbk {

StandardizationChannelTables sample_standardization(const EmpiricalStandardization& g, uint32_t size) {
  if (size < kLutMinSize || size > kLutMaxSize)
    throw Error(ExitCode::runtime_failure, "internal: lut size " + std::to_string(size) + " outside 2..65536");
  if (g.max() - g.min() < kFlatChannelSpread) return StandardizationChannelTables({float(g.min())}, {0.0f});

  // Candidate x: both grids and the atoms (min and max are float texel values, exact; so are the atoms).
  std::vector<float> x;
  x.reserve(3 * size_t(size));
  for (uint32_t j = 0; j < size; ++j) {
    x.push_back(float(lut_sample_position(g.min(), g.max(), size, j)));
    x.push_back(float(g.inverse(lut_sample_position(g.gaussian_min(), g.gaussian_max(), size, j))));
  }
  // c_k >= N / size: the run holds about a z-grid step's worth of rank or more (so at most `size` atoms).
  const uint64_t heavy = (uint64_t(g.count()) + size - 1) / size;
  const std::vector<float> atoms = g.values_counted_at_least(std::max<uint64_t>(heavy, 1));  // ascending
  x.insert(x.end(), atoms.begin(), atoms.end());
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  x.front() = float(g.min()), x.back() = float(g.max());  // the clamped ends

  // Exact G at each knot, rounded to float; keep z strictly increasing. G is non-decreasing and so is float
  // rounding, so a conflict is a knot whose z rounds onto its predecessor's: one of the two goes, and the one that
  // stays is, in this order, a domain end, an atom, the earlier one.
  std::vector<float> kx, kz;
  std::vector<char> pinned;  // a domain end or an atom
  kx.reserve(x.size());
  kz.reserve(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const float z = float(g.forward(x[i]));
    const bool pin = i == 0 || i + 1 == x.size() || std::binary_search(atoms.begin(), atoms.end(), x[i]);
    while (pin && kz.size() > 1 && kz.back() >= z && !pinned.back()) kx.pop_back(), kz.pop_back(), pinned.pop_back();
    if (!kz.empty() && z <= kz.back()) continue;
    kx.push_back(x[i]);
    kz.push_back(z);
    pinned.push_back(pin);
  }
  return StandardizationChannelTables(std::move(kx), std::move(kz));
}

}  // namespace mbk
