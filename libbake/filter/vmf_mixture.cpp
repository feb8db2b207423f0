// Spherical EM for vMF mixtures (see vmf_mixture.h).
#include "libbake/filter/vmf_mixture.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/core/vmf_lobe.h"

namespace mbk {
namespace {

constexpr size_t kChunk = kVmfSumChunk;
// Terms of a log-sum-exp more than 40 nats below the largest are taken as 0 rather than passed to exp: e^-40 ~
// 4e-18 is below half an ulp of the sum (>= 1), so the normaliser is unchanged, and a responsibility that small
// moves the M-step sums by less than 1e-17 relative. At high kappa most lobes are that far from most normals.
constexpr double kNegligibleLog = -40.0;

// Per-lobe sums of one E-step over a chunk of normals, plus the chunk's log-likelihood.
struct Partial {
  std::vector<double> mass;  // sum w z
  std::vector<Vec3> moment;  // sum w z n
  double log_likelihood = 0.0;
};

struct LobeTerms {
  std::vector<double> log_scale, kappa;  // log(alpha C(kappa)) - kappa, kappa; -inf scale for empty lobes
  std::vector<Vec3> mu;
};

LobeTerms lobe_terms(const std::vector<VmfComponent>& mixture) {
  LobeTerms t;
  for (const VmfComponent& c : mixture) {
    const bool live = c.alpha > 0.0;
    // log alpha + log g = log alpha + vmf_log_density(kappa, cos) = (log alpha + log_density(kappa, 0) + kappa) + kappa
    // cos - kappa
    t.log_scale.push_back(live ? std::log(c.alpha) + vmf_log_density(c.kappa, 1.0) - c.kappa
                               : -std::numeric_limits<double>::infinity());
    t.kappa.push_back(c.kappa);
    t.mu.push_back(c.mu);
  }
  return t;
}

// Log-domain responsibilities of normal n into z (size J); returns log sum_j alpha_j g_j(n).
double responsibilities(const LobeTerms& t, const Vec3& n, std::vector<double>& z) {
  const size_t J = t.kappa.size();
  double top = -std::numeric_limits<double>::infinity();
  for (size_t j = 0; j < J; ++j) {
    z[j] = t.log_scale[j] == -std::numeric_limits<double>::infinity() ? t.log_scale[j]
                                                                      : t.log_scale[j] + t.kappa[j] * t.mu[j].dot(n);
    top = std::max(top, z[j]);
  }
  double sum = 0.0;
  for (size_t j = 0; j < J; ++j) {
    const double d = z[j] - top;
    z[j] = d < kNegligibleLog ? 0.0 : std::exp(d);  // in [0, 1]; exactly 1 for the largest
    sum += z[j];
  }
  for (size_t j = 0; j < J; ++j) z[j] /= sum;
  return top + std::log(sum);
}

// log sum_j alpha_j g_j(n), the same log-sum-exp as responsibilities() without storing the terms.
double log_mixture_density(const LobeTerms& t, const Vec3& n) {
  double top = -std::numeric_limits<double>::infinity();
  for (size_t j = 0; j < t.kappa.size(); ++j)
    if (t.log_scale[j] != -std::numeric_limits<double>::infinity())
      top = std::max(top, t.log_scale[j] + t.kappa[j] * t.mu[j].dot(n));
  if (top == -std::numeric_limits<double>::infinity()) return top;
  double sum = 0.0;
  for (size_t j = 0; j < t.kappa.size(); ++j) {
    const double d = t.log_scale[j] + t.kappa[j] * t.mu[j].dot(n) - top;
    if (d >= kNegligibleLog) sum += std::exp(d);
  }
  return top + std::log(sum);
}

// One E-step with sufficient statistics, chunked for determinism.
Partial e_step(std::span<const WeightedNormal> normals, const LobeTerms& t) {
  const size_t J = t.kappa.size(), chunks = (normals.size() + kChunk - 1) / kChunk;
  std::vector<Partial> partials(chunks);
  auto run = [&](int64_t c) {
    Partial& p = partials[size_t(c)];
    p.mass.assign(J, 0.0);
    p.moment.assign(J, Vec3::Zero());
    std::vector<double> z(J);
    const size_t end = std::min(normals.size(), size_t(c + 1) * kChunk);
    for (size_t i = size_t(c) * kChunk; i < end; ++i) {
      const WeightedNormal& wn = normals[i];
      p.log_likelihood += wn.w * responsibilities(t, wn.n, z);
      for (size_t j = 0; j < J; ++j) {
        if (z[j] == 0.0) continue;
        p.mass[j] += wn.w * z[j];
        p.moment[j] += (wn.w * z[j]) * wn.n;
      }
    }
  };
  if (chunks > 1)
    parallel_for(0, int64_t(chunks), run);
  else
    run(0);
  Partial total = std::move(partials[0]);
  for (size_t c = 1; c < chunks; ++c) {
    total.log_likelihood += partials[c].log_likelihood;
    for (size_t j = 0; j < J; ++j) {
      total.mass[j] += partials[c].mass[j];
      total.moment[j] += partials[c].moment[j];
    }
  }
  return total;
}

// Sum over normals of term(i), in fixed chunks added in chunk order (deterministic whatever the threads).
template <typename F>
double chunked_sum(size_t count, F&& term) {
  const size_t chunks = (count + kChunk - 1) / kChunk;
  std::vector<double> partial(chunks, 0.0);
  auto run = [&](int64_t c) {
    const size_t end = std::min(count, size_t(c + 1) * kChunk);
    for (size_t i = size_t(c) * kChunk; i < end; ++i) partial[size_t(c)] += term(i);
  };
  if (chunks > 1)
    parallel_for(0, int64_t(chunks), run);
  else if (chunks == 1)
    run(0);
  double total = 0.0;
  for (double p : partial) total += p;
  return total;
}

// log(e^a + e^b) without overflow.
double log_add(double a, double b) {
  const double top = std::max(a, b);
  if (top == -std::numeric_limits<double>::infinity()) return top;
  return top + std::log1p(std::exp(std::min(a, b) - top));
}

// The collapse guard's re-seed (vmf_mixture.h): lobe `slot` (already emptied) goes to the best of the
// candidate normals and concentrations, with amplitude 1/J.
void reseed(std::span<const WeightedNormal> normals, std::vector<VmfComponent>& mixture, size_t slot,
            double kappa_max) {
  constexpr size_t kCandidates = 16;
  const size_t N = normals.size(), J = mixture.size();
  double live_alpha = 0.0, pooled = 0.0;
  for (const VmfComponent& c : mixture)
    if (c.alpha > 0.0) live_alpha += c.alpha, pooled += c.alpha * c.r.norm();
  const double kappa = vmf_kappa_from_mean_length(pooled / live_alpha, kappa_max);
  const LobeTerms t = lobe_terms(mixture);
  std::vector<double> log_p(N);
  for (size_t i = 0; i < N; ++i) log_p[i] = log_mixture_density(t, normals[i].n) - std::log(live_alpha);
  std::vector<size_t> order(N);
  for (size_t i = 0; i < N; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return log_p[a] < log_p[b]; });
  std::vector<size_t> candidates;
  double cumulative = 0.0;
  for (size_t r = 0, k = 0; r < N && k < kCandidates; ++r) {
    if (cumulative >= double(k) / kCandidates) {
      candidates.push_back(order[r]);
      while (k < kCandidates && cumulative >= double(k) / kCandidates) ++k;
    }
    cumulative += normals[order[r]].w;
  }
  const double a = 1.0 / double(J), log_keep = std::log1p(-a), log_a = std::log(a);
  size_t best = candidates[0];
  double best_gain = -std::numeric_limits<double>::infinity(), best_kappa = kappa;
  for (size_t c : candidates) {
    const Vec3 mu = normals[c].n;
    for (double k : {kappa, kappa_max}) {
      const double gain = chunked_sum(N, [&](size_t i) {
        const double with = log_add(log_keep + log_p[i], log_a + vmf_log_density(k, mu.dot(normals[i].n)));
        return normals[i].w * (with - log_p[i]);
      });
      if (gain > best_gain) best_gain = gain, best = c, best_kappa = k;
    }
  }
  for (VmfComponent& c : mixture) c.alpha *= (1.0 - a) / live_alpha;
  VmfComponent& lobe = mixture[slot];
  lobe.alpha = a;
  lobe.kappa = best_kappa;
  lobe.mu = normals[best].n;
  lobe.r = vmf_mean_length(best_kappa) * lobe.mu;
}

}  // namespace

double vmf_mixture_log_likelihood(std::span<const WeightedNormal> normals, const std::vector<VmfComponent>& mixture) {
  const LobeTerms t = lobe_terms(mixture);
  return chunked_sum(normals.size(), [&](size_t i) { return normals[i].w * log_mixture_density(t, normals[i].n); });
}

void set_lobe_from_resultant(VmfComponent& lobe, double kappa_max) {
  const double length = lobe.r.norm();
  lobe.kappa = vmf_kappa_from_mean_length(length, kappa_max);
  lobe.mu = length > 0.0 ? Vec3(lobe.r / length) : Vec3::UnitZ();
}

EmReport fit_vmf_mixture(std::span<const WeightedNormal> normals, std::vector<VmfComponent>& mixture,
                         const EmOptions& options, std::span<const Vec3> align_targets) {
  if (normals.empty()) throw Error(ExitCode::runtime_failure, "internal: vMF fit of a texel without normals");
  if (std::none_of(mixture.begin(), mixture.end(), [](const VmfComponent& c) { return c.alpha > 0.0; }))
    throw Error(ExitCode::runtime_failure, "internal: vMF fit started without a lobe");
  const size_t J = mixture.size();
  EmReport report;
  int reseeds_left = int(J);
  std::vector<VmfComponent> before_reseed;  // the fixed point a trial re-seed must beat
  double before_reseed_ll = 0.0;
  double previous = -std::numeric_limits<double>::infinity();
  for (int it = 0; it < options.max_iterations; ++it) {
    const Partial p = e_step(normals, lobe_terms(mixture));
    report.iterations = it + 1;
    report.log_likelihood = p.log_likelihood;
    // M-step.
    for (size_t j = 0; j < J; ++j) {
      VmfComponent& c = mixture[j];
      if (c.alpha <= 0.0) continue;
      if (p.mass[j] < kEmptyAmplitude) {
        c = VmfComponent{};
        continue;
      }
      c.alpha = p.mass[j];
      c.r = p.moment[j] / p.mass[j];
      set_lobe_from_resultant(c, options.kappa_max);
      if (options.align > 0.0 && !align_targets.empty()) {
        const Vec3 pulled = c.r + options.align * align_targets[j];  // [Han07] Eq. (7.26)
        if (pulled.norm() > 0.0) c.mu = pulled.normalized();
      }
    }
    const bool stalled = p.log_likelihood - previous < options.tolerance;
    previous = p.log_likelihood;
    if (!stalled && it + 1 < options.max_iterations) continue;
    report.converged = stalled;
    // A fixed point (or the budget spent). A trial re-seed that did not end higher by `tolerance` is undone, and
    // the guard stops.
    if (!before_reseed.empty()) {
      if (p.log_likelihood < before_reseed_ll + options.tolerance) {
        mixture = std::move(before_reseed);
        report.log_likelihood = before_reseed_ll;
        --report.reseeds;
        report.converged = true;
        break;
      }
      before_reseed.clear();
    }
    // The collapse guard: the weakest (smallest) live lobe gets a trial re-seed.
    size_t weakest = J, live = 0;
    for (size_t j = 0; j < J; ++j) {
      if (mixture[j].alpha <= 0.0) continue;
      ++live;
      if (weakest == J || mixture[j].alpha < mixture[weakest].alpha) weakest = j;
    }
    if (!options.reseed || weakest == J || live < 2 || reseeds_left == 0 || it + 1 == options.max_iterations) break;
    before_reseed = mixture;
    before_reseed_ll = p.log_likelihood;
    mixture[weakest] = VmfComponent{};
    reseed(normals, mixture, weakest, options.kappa_max);
    --reseeds_left;
    ++report.reseeds;
    previous = -std::numeric_limits<double>::infinity();
  }
  // The amplitudes of the live lobes sum to the mass of the last E-step (1 up to rounding); renormalise so
  // that stored amplitudes sum to 1.
  double total = 0.0;
  for (const VmfComponent& c : mixture) total += c.alpha;
  for (VmfComponent& c : mixture) c.alpha /= total;
  return report;
}

std::vector<VmfComponent> farthest_apart_seeds(std::span<const VmfComponent> candidates, int J, SeedRule rule) {
  // Smallest 1 - cos between two chosen seeds: closer lobes count as the same direction.
  constexpr double kDistinctDirection = 1e-12;
  std::vector<VmfComponent> seeds(static_cast<size_t>(J));
  if (candidates.empty()) return seeds;
  // The mass-weighted rule weighs each candidate by the amplitude of all candidates in its direction (an atom of
  // identical normals spread over several children counts whole).
  std::vector<double> mass(candidates.size());
  for (size_t c = 0; c < candidates.size(); ++c)
    for (size_t d = 0; d < candidates.size(); ++d)
      if (rule == SeedRule::mass_weighted ? 1.0 - candidates[c].mu.dot(candidates[d].mu) <= kDistinctDirection : c == d)
        mass[c] += candidates[d].alpha;
  size_t first = 0;
  for (size_t c = 1; c < candidates.size(); ++c)
    if (mass[c] > mass[first]) first = c;
  std::vector<double> distance(candidates.size(), 2.0);  // smallest 1 - cos to a chosen seed
  size_t chosen = 0, next = first;
  while (chosen < size_t(J)) {
    seeds[chosen++] = candidates[next];
    for (size_t c = 0; c < candidates.size(); ++c)
      distance[c] = std::min(distance[c], 1.0 - candidates[c].mu.dot(candidates[next].mu));
    next = size_t(std::max_element(distance.begin(), distance.end()) - distance.begin());
    if (distance[next] <= kDistinctDirection) break;
    if (rule == SeedRule::mass_weighted) {
      double best = -1.0;
      for (size_t c = 0; c < candidates.size(); ++c)
        if (distance[c] > kDistinctDirection && mass[c] * distance[c] > best) best = mass[c] * distance[c], next = c;
    }
  }
  for (size_t s = 0; s < chosen; ++s) seeds[s].alpha = 1.0 / double(chosen);
  return seeds;
}

std::vector<double> lobe_features(std::span<const WeightedNormal> normals, std::span<const float> features,
                                  int feature_count, const std::vector<VmfComponent>& mixture) {
  const size_t J = mixture.size(), F = size_t(feature_count);
  const LobeTerms t = lobe_terms(mixture);
  std::vector<double> sum(J * F, 0.0), mass(J, 0.0), z(J);
  for (size_t i = 0; i < normals.size(); ++i) {
    responsibilities(t, normals[i].n, z);
    for (size_t j = 0; j < J; ++j) {
      const double wz = normals[i].w * z[j];
      mass[j] += wz;
      for (size_t f = 0; f < F; ++f) sum[j * F + f] += wz * features[i * F + f];  // [Han07] Eq. (7.25)
    }
  }
  for (size_t j = 0; j < J; ++j)
    for (size_t f = 0; f < F; ++f) sum[j * F + f] = mass[j] > 0.0 ? sum[j * F + f] / mass[j] : 0.0;
  return sum;
}

}  // namespace mbk
