// Greedy k-means++ and Lloyd's iterations on sorted 1-D values, and uniform bins (see adaptive_theta_bins.h).
#include "libbake/histogram/adaptive_theta_bins.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "formats/histogram_layout.h"
#include "libbake/core/hash.h"

namespace mbk {
namespace {

constexpr uint32_t kMaxLloydIterations = 1000;

// A uniform double in [0, 1) with 53 random bits, from the seed and two indices.
double uniform(uint64_t seed, uint32_t a, uint32_t b) {
  const uint32_t s0 = uint32_t(seed), s1 = uint32_t(seed >> 32);
  const uint64_t hi = hash4(s0, s1, a, 2 * b), lo = hash4(s0, s1, a, 2 * b + 1);
  return double(((hi << 32) | lo) >> 11) * 0x1p-53;
}

// Distinct sorted values with their multiplicities and prefix sums of weight and weighted value.
struct WeightedValues {
  std::vector<double> value, weight;
  std::vector<double> prefix_weight{0.0}, prefix_sum{0.0};  // over [0, i)
  size_t size() const { return value.size(); }
  double mean(size_t begin, size_t end) const {
    const double m = (prefix_sum[end] - prefix_sum[begin]) / (prefix_weight[end] - prefix_weight[begin]);
    return std::clamp(m, value[begin], value[end - 1]);  // rounding of the differences must not leave the run
  }
};

WeightedValues merge_sorted(const std::vector<double>& sorted) {
  WeightedValues v;
  for (double t : sorted) {
    if (v.value.empty() || t != v.value.back()) {
      v.value.push_back(t);
      v.weight.push_back(0.0);
    }
    v.weight.back() += 1.0;
  }
  for (size_t i = 0; i < v.size(); ++i) {
    v.prefix_weight.push_back(v.prefix_weight.back() + v.weight[i]);
    v.prefix_sum.push_back(v.prefix_sum.back() + v.weight[i] * v.value[i]);
  }
  return v;
}

// Greedy k-means++ seeding on m > k distinct values: k distinct values, sorted.
std::vector<double> greedy_kmeanspp_seeds(const WeightedValues& v, uint32_t k, uint64_t seed) {
  const size_t m = v.size();
  auto draw = [&](const std::vector<double>& cumulative, uint32_t step, uint32_t candidate) {
    const double u = uniform(seed, step, candidate) * cumulative.back();
    size_t i = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
    // u rounded up to the total: the last value of positive mass.
    if (i == m)
      for (i = m - 1; i > 0 && cumulative[i] == cumulative[i - 1];) --i;
    return i;
  };
  std::vector<double> cumulative(m);
  for (size_t i = 0; i < m; ++i) cumulative[i] = v.prefix_weight[i + 1];
  std::vector<double> centres = {v.value[draw(cumulative, 0, 0)]};
  std::vector<double> d2(m);
  for (size_t i = 0; i < m; ++i) d2[i] = (v.value[i] - centres[0]) * (v.value[i] - centres[0]);
  const uint32_t candidates = 2 + uint32_t(std::log(double(k)));
  for (uint32_t step = 1; step < k; ++step) {
    double running = 0.0;
    for (size_t i = 0; i < m; ++i) cumulative[i] = running += v.weight[i] * d2[i];
    // m > k distinct values and fewer than k centres: some value is not a centre, so the total is positive, and
    // a draw lands only on a value of positive D^2, never on a chosen centre.
    double best_cost = INFINITY, best = 0.0;
    for (uint32_t c = 0; c < candidates; ++c) {
      const double candidate = v.value[draw(cumulative, step, c)];
      double cost = 0.0;
      for (size_t i = 0; i < m; ++i) {
        const double d = v.value[i] - candidate;
        cost += v.weight[i] * std::min(d2[i], d * d);
      }
      if (cost < best_cost) {
        best_cost = cost;
        best = candidate;
      }
    }
    centres.push_back(best);
    for (size_t i = 0; i < m; ++i) d2[i] = std::min(d2[i], (v.value[i] - best) * (v.value[i] - best));
  }
  std::sort(centres.begin(), centres.end());
  return centres;
}

// The first index of each centre's run: values at or above the midpoint below a centre belong to it (the bins'
// half-open rule), so the clustering is the one the bins count.
std::vector<size_t> run_starts(const WeightedValues& v, const std::vector<double>& centres) {
  std::vector<size_t> starts = {0};
  for (size_t j = 1; j < centres.size(); ++j) {
    const double edge = 0.5 * (centres[j - 1] + centres[j]);
    starts.push_back(size_t(std::lower_bound(v.value.begin(), v.value.end(), edge) - v.value.begin()));
  }
  starts.push_back(v.size());
  return starts;
}

// The edges (0, the midpoints of the centres, pi/2) and the RMS distance of the values to their bin's centre.
void finish_bins(const WeightedValues& v, ThetaBins& bins) {
  bins.edges = {0.0};
  for (size_t j = 1; j < bins.centres.size(); ++j) bins.edges.push_back(0.5 * (bins.centres[j - 1] + bins.centres[j]));
  bins.edges.push_back(kHistogramThetaMax);
  double squared = 0.0;
  for (size_t i = 0; i < v.size(); ++i) {
    const double d = v.value[i] - bins.centres[histogram_theta_bin(bins.edges, v.value[i])];
    squared += v.weight[i] * d * d;
  }
  bins.rms_error = std::sqrt(squared / v.prefix_weight.back());
}

}  // namespace

ThetaBins adaptive_theta_bins(std::vector<double> thetas, uint32_t k, uint64_t seed) {
  if (thetas.empty() || k == 0) throw std::invalid_argument("adaptive_theta_bins: no values or no bins");
  std::sort(thetas.begin(), thetas.end());
  const WeightedValues v = merge_sorted(thetas);
  ThetaBins bins;
  bins.distinct_values = v.size();
  if (v.size() <= k) {
    bins.centres = v.value;
  } else {
    bins.centres = greedy_kmeanspp_seeds(v, k, seed);
    std::vector<size_t> starts = run_starts(v, bins.centres);
    for (; bins.lloyd_iterations < kMaxLloydIterations; ++bins.lloyd_iterations) {
      std::vector<double> next(k);
      for (uint32_t j = 0; j < k; ++j) next[j] = v.mean(starts[j], starts[j + 1]);
      const std::vector<size_t> next_starts = run_starts(v, next);
      bool empty_run = false;
      for (uint32_t j = 0; j < k; ++j) empty_run = empty_run || next_starts[j] == next_starts[j + 1];
      if (empty_run) break;
      const bool converged = next == bins.centres;
      bins.centres = std::move(next);
      starts = next_starts;
      if (converged) break;
    }
  }
  finish_bins(v, bins);
  return bins;
}

ThetaBins uniform_theta_bins(std::vector<double> thetas, uint32_t k) {
  if (thetas.empty() || k == 0) throw std::invalid_argument("uniform_theta_bins: no values or no bins");
  std::sort(thetas.begin(), thetas.end());
  const WeightedValues v = merge_sorted(thetas);
  ThetaBins bins;
  bins.distinct_values = v.size();
  for (uint32_t j = 0; j < k; ++j) bins.centres.push_back((j + 0.5) * kHistogramThetaMax / k);
  finish_bins(v, bins);
  return bins;
}

}  // namespace mbk
