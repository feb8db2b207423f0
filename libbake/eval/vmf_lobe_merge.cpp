// Merging the vMF lobes of a lookup by direction (see vmf_lobe_merge.h).
#include "libbake/eval/vmf_lobe_merge.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace mbk {
namespace {

// Unit direction and angular spread sqrt(2 (1 - |r|)) of premultiplied (alpha, alpha r).
struct Direction {
  Vec3 mu = Vec3::UnitZ();
  double spread = std::sqrt(2.0);
};

Direction direction_of(double alpha, const Vec3& alpha_r) {
  Direction d;
  const double len = alpha_r.norm();
  if (!(alpha > 0.0) || !(len > 0.0)) return d;
  d.mu = alpha_r / len;
  d.spread = std::sqrt(2.0 * std::max(0.0, 1.0 - std::min(1.0, len / alpha)));
  return d;
}

}  // namespace

std::vector<VmfLobeShape> merge_vmf_lobes(std::span<const WeightedVmfLobe> candidates, size_t max_lobes,
                                          double kappa_max, size_t feature_count, std::vector<double>* alpha_y) {
  if (max_lobes == 0) return {};
  // Groups by decreasing total weight, each group's lobes by decreasing weight.
  std::vector<double> group_weight;
  for (const WeightedVmfLobe& c : candidates) {
    if (c.group >= group_weight.size()) group_weight.resize(c.group + 1, 0.0);
    group_weight[c.group] += std::max(0.0, c.alpha);
  }
  std::vector<size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const WeightedVmfLobe &x = candidates[a], &y = candidates[b];
    if (x.group != y.group && group_weight[x.group] != group_weight[y.group])
      return group_weight[x.group] > group_weight[y.group];
    return x.group != y.group ? x.group < y.group : x.alpha > y.alpha;
  });
  const size_t first_group = order.empty() ? 0 : candidates[order[0]].group;
  std::vector<double> alpha;
  std::vector<Vec3> alpha_r;
  std::vector<Direction> directions;
  std::vector<double> features;
  for (const size_t i : order) {
    const WeightedVmfLobe& k = candidates[i];
    if (!(k.alpha > 0.0)) continue;
    const Direction dk = direction_of(k.alpha, k.alpha_r);
    // The cost of joining lobe c: how much the mass-weighted spread grows.
    const auto cost = [&](size_t c) {
      const double merged = (alpha[c] + k.alpha) * direction_of(alpha[c] + k.alpha, alpha_r[c] + k.alpha_r).spread;
      return merged - alpha[c] * directions[c].spread - k.alpha * dk.spread;
    };
    size_t best = alpha.size(), best_compatible = alpha.size();
    double best_cost = INFINITY, best_compatible_cost = INFINITY;
    for (size_t c = 0; c < alpha.size(); ++c) {
      const double added = cost(c);
      if (added < best_cost) best_cost = added, best = c;
      if (!(added < best_compatible_cost)) continue;  // compatible or not, c is not the best compatible lobe
      const double reach = dk.spread + directions[c].spread + kVmfMergeFloor;  // angle(mu_c, mu_k) <= reach
      if (reach >= std::numbers::pi || dk.mu.dot(directions[c].mu) >= std::cos(reach))
        best_compatible_cost = added, best_compatible = c;
    }
    // The heaviest texel's own lobes are the fit's separate components: each keeps a lobe of its own.
    size_t into = k.group == first_group ? alpha.size() : best_compatible;
    if (into == alpha.size() && alpha.size() == max_lobes) into = best;
    if (into == alpha.size()) {
      alpha.push_back(0.0);
      alpha_r.push_back(Vec3::Zero());
      directions.emplace_back();
      features.resize(features.size() + feature_count, 0.0);
    }
    alpha[into] += k.alpha;
    alpha_r[into] += k.alpha_r;
    directions[into] = direction_of(alpha[into], alpha_r[into]);
    for (size_t f = 0; f < feature_count && f < k.alpha_y.size(); ++f)
      features[into * feature_count + f] += k.alpha_y[f];
  }
  std::vector<VmfLobeShape> lobes(max_lobes);
  for (size_t c = 0; c < alpha.size(); ++c) lobes[c] = vmf_lobe_from_premultiplied(alpha[c], alpha_r[c], kappa_max);
  if (alpha_y) {
    features.resize(max_lobes * feature_count, 0.0);
    alpha_y->insert(alpha_y->end(), features.begin(), features.end());
  }
  return lobes;
}

}  // namespace mbk
