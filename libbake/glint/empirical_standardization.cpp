// The exact standardization transform of one channel (see empirical_standardization.h).
#include "libbake/glint/empirical_standardization.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "formats/error.h"
#include "libbake/core/float_sort.h"
#include "libbake/glint/standard_normal.h"

namespace mbk {

EmpiricalStandardization::EmpiricalStandardization(std::vector<float> sorted) {
  if (sorted.empty()) throw Error(ExitCode::runtime_failure, "internal: standardizing an empty channel");
  if (sorted.size() > size_t(INT32_MAX))
    throw Error(ExitCode::runtime_failure, "internal: more than 2^31 - 1 values to standardize");
  for (float& v : sorted) {
    if (!std::isfinite(v))
      throw Error(ExitCode::runtime_failure, "internal: non-finite value in a channel to standardize");
    v += 0.0f;  // -0 + 0 = +0: one node for both zeros
  }
  sort_floats(sorted);
  // Runs of equal values: [begin, end) in sorted order; 2 r_k = begin + end (twice the middle of the run).
  size_t runs = 1;
  for (size_t i = 1; i < sorted.size(); ++i) runs += sorted[i] != sorted[i - 1];
  values_.reserve(runs);
  twice_rank_.reserve(runs);
  for (size_t begin = 0; begin < sorted.size();) {
    size_t end = begin + 1;
    while (end < sorted.size() && sorted[end] == sorted[begin]) ++end;
    values_.push_back(sorted[begin]);
    twice_rank_.push_back(uint32_t(begin + end));
    begin = end;
  }
  twice_count_ = 2 * uint64_t(sorted.size());
  gaussian_min_ = gaussian_of_twice_rank(double(twice_rank_.front()));
  gaussian_max_ = gaussian_of_twice_rank(double(twice_rank_.back()));
}

// z = Phi^-1(m / 2N), through the upper tail's own mass (2N - m) / 2N above the median so that both ends keep
// full relative precision (Phi^-1(1 - q) = -Phi^-1(q)).
double EmpiricalStandardization::gaussian_of_twice_rank(double twice_rank) const {
  const double total = double(twice_count_);
  if (2.0 * twice_rank <= total) return standard_normal_quantile(twice_rank / total);
  return -standard_normal_quantile((total - twice_rank) / total);
}

std::vector<float> EmpiricalStandardization::values_counted_at_least(uint64_t min_count) const {
  std::vector<float> heavy;
  uint64_t begin = 0;  // c_k = 2 r_k - 2 begin_k
  for (size_t k = 0; k < values_.size(); ++k) {
    const uint64_t count = twice_rank_[k] - 2 * begin;
    if (count >= min_count) heavy.push_back(values_[k]);
    begin += count;
  }
  return heavy;
}

double EmpiricalStandardization::forward(double x) const {
  if (x >= values_.back()) return gaussian_max_;
  if (!(x > values_.front())) return gaussian_min_;
  // u_k <= x < u_{k+1}, with k + 1 <= K - 1 because x < u_K.
  const size_t k = size_t(std::upper_bound(values_.begin(), values_.end(), x) - values_.begin()) - 1;
  const double u0 = values_[k], u1 = values_[k + 1];
  const double t = (x - u0) / (u1 - u0);
  const double r0 = twice_rank_[k], r1 = twice_rank_[k + 1];
  return gaussian_of_twice_rank(r0 + t * (r1 - r0));
}

double EmpiricalStandardization::inverse(double z) const {
  if (z >= gaussian_max_) return values_.back();
  if (!(z > gaussian_min_)) return values_.front();
  // Here K >= 2 (a constant channel has gaussian_min = gaussian_max). Twice-rank mass of z, through the tail
  // on z's side.
  const double total = double(twice_count_);
  const double m = z <= 0.0 ? total * standard_normal_cdf(z) : total - total * standard_normal_cdf(-z);
  // r_k <= m < r_{k+1}; rounding in Phi may put m a hair outside (r_1, r_K): clamp the interval and t.
  size_t k = size_t(
      std::upper_bound(twice_rank_.begin(), twice_rank_.end(), m, [](double a, uint32_t b) { return a < double(b); }) -
      twice_rank_.begin());
  k = std::clamp<size_t>(k, 1, values_.size() - 1) - 1;
  const double r0 = twice_rank_[k], r1 = twice_rank_[k + 1];
  const double t = std::clamp((m - r0) / (r1 - r0), 0.0, 1.0);
  const double u0 = values_[k], u1 = values_[k + 1];
  return u0 + t * (u1 - u0);
}

}  // namespace mbk
