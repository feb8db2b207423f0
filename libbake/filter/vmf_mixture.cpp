// Spherical EM for vMF mixtures (see vmf_mixture.h).
#include "libbake/filter/vmf_mixture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/filter/vmf_e_step.h"

namespace mbk {
namespace {

constexpr size_t kChunk = kVmfSumChunk;
// The guard's log_add drops a term this far below the other, as the E-step does (vmf_e_step.h).
constexpr double kNegligibleLog = -40.0;

// log sum_j alpha_j g_j(n), the E-step's log-sum-exp without keeping the responsibilities.
double log_mixture_density(const LobeTerms& t, const Vec3& n) {
  double z[kVmfMaxLobes];
  return vmf_responsibilities(t, n, z);
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

// log(e^a + e^b) without overflow; the smaller term is dropped when negligible (kNegligibleLog).
double log_add(double a, double b) {
  const double top = std::max(a, b), d = std::min(a, b) - top;
  if (top == -std::numeric_limits<double>::infinity() || d < kNegligibleLog) return top;
  return top + std::log1p(std::exp(d));
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
  const double log_live_alpha = std::log(live_alpha);
  for (size_t i = 0; i < N; ++i) log_p[i] = log_mixture_density(t, normals[i].n) - log_live_alpha;
  std::vector<size_t> order(N);
  for (size_t i = 0; i < N; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return log_p[a] < log_p[b]; });
  std::vector<size_t> candidates;
  double cumulative = 0.0;
  // The normal at quantile q is the one whose interval of cumulative weight contains q (a heavy chunk can hold
  // several).
  for (size_t r = 0, k = 0; r < N && k < kCandidates; ++r) {
    cumulative += normals[order[r]].w;
    if (cumulative > double(k) / kCandidates) {
      candidates.push_back(order[r]);
      while (k < kCandidates && cumulative > double(k) / kCandidates) ++k;
    }
  }
  const double a = 1.0 / double(J), log_keep = std::log1p(-a), log_a = std::log(a);
  Vec3 best = Vec3::UnitZ();
  double best_gain = -std::numeric_limits<double>::infinity(), best_kappa = kappa;
  for (size_t c : candidates) {
    // A chunk's mean (vmf_normal_chunks.h) is shorter than 1; a chunk of opposite normals has no direction.
    const double length = normals[c].n.norm();
    if (!(length > 0.0)) continue;
    const Vec3 mu = normals[c].n / length;
    for (double k : {kappa, kappa_max}) {
      const double log_peak = log_a + vmf_log_density(k, 1.0);  // log(a g(mu; k, mu))
      const double gain = chunked_sum(N, [&](size_t i) {
        const double with = log_add(log_keep + log_p[i], log_peak + k * (mu.dot(normals[i].n) - 1.0));
        return normals[i].w * (with - log_p[i]);
      });
      if (gain > best_gain) best_gain = gain, best = mu, best_kappa = k;
    }
  }
  for (VmfComponent& c : mixture) c.alpha *= (1.0 - a) / live_alpha;
  VmfComponent& lobe = mixture[slot];
  lobe.alpha = a;
  lobe.kappa = best_kappa;
  lobe.mu = best;
  lobe.r = vmf_mean_length(best_kappa) * lobe.mu;
}

// The M-step from the sums of an E-step (vmf_mixture.h); a lobe whose mass is below kEmptyAmplitude is emptied.
void m_step(const EStepSums& p, std::vector<VmfComponent>& mixture, const EmOptions& options,
            std::span<const Vec3> align_targets) {
  for (size_t j = 0; j < mixture.size(); ++j) {
    VmfComponent& c = mixture[j];
    if (c.alpha <= 0.0) continue;
    if (p.mass[j] < kEmptyAmplitude) {
      c = VmfComponent{};
      continue;
    }
    c.alpha = p.mass[j];
    c.r = Vec3(p.moment[j][0], p.moment[j][1], p.moment[j][2]) / p.mass[j];
    set_lobe_from_resultant(c, options.kappa_max);
    if (options.align > 0.0 && !align_targets.empty()) {
      const Vec3 pulled = c.r + options.align * align_targets[j];  // [Han07] Eq. (7.26)
      if (pulled.norm() > 0.0) c.mu = pulled.normalized();
    }
  }
}

// The SQUAREM extrapolation (vmf_mixture.h) of three successive EM states theta_0, theta_1 = M(theta_0),
// theta_2 = M(theta_1) in the parameters (alpha_j, r_j) of their live lobes: theta_0 - 2 s d + s^2 v with
// d = theta_1 - theta_0, v = theta_2 - 2 theta_1 + theta_0, s = -|d| / |v|, s moved halfway to -1 while a
// lobe would get alpha <= 0 or |r| > 1. Amplitudes renormalised to sum 1. Empty when there is nothing to
// extrapolate (s >= -1 gives theta_2 itself, or the live lobes differ).
std::vector<VmfComponent> squarem_extrapolation(const std::vector<VmfComponent>& t0,
                                                const std::vector<VmfComponent>& t1,
                                                const std::vector<VmfComponent>& t2, double kappa_max) {
  // Lobes at the kappa cap (atoms) are not extrapolated: they keep theta_2's parameters.
  const auto held = [&](size_t j) { return std::max({t0[j].kappa, t1[j].kappa, t2[j].kappa}) >= kappa_max; };
  double d2 = 0.0, v2 = 0.0;
  for (size_t j = 0; j < t0.size(); ++j) {
    const bool live = t0[j].alpha > 0.0;
    if (live != (t1[j].alpha > 0.0) || live != (t2[j].alpha > 0.0)) return {};
    if (!live || held(j)) continue;
    const double da = t1[j].alpha - t0[j].alpha, va = t2[j].alpha - 2.0 * t1[j].alpha + t0[j].alpha;
    d2 += da * da + (t1[j].r - t0[j].r).squaredNorm();
    v2 += va * va + (t2[j].r - 2.0 * t1[j].r + t0[j].r).squaredNorm();
  }
  if (!(v2 > 0.0)) return {};
  for (double s = -std::sqrt(d2 / v2); s < -1.0 - 1e-3; s = 0.5 * (s - 1.0)) {
    std::vector<VmfComponent> out(t0.size());
    bool valid = true;
    double total = 0.0;
    for (size_t j = 0; j < t0.size() && valid; ++j) {
      if (!(t0[j].alpha > 0.0)) continue;
      if (held(j)) {
        out[j] = t2[j];
        total += t2[j].alpha;
        continue;
      }
      const auto step = [s](double a0, double a1, double a2) {
        return a0 - 2.0 * s * (a1 - a0) + s * s * (a2 - 2.0 * a1 + a0);
      };
      VmfComponent& c = out[j];
      c.alpha = step(t0[j].alpha, t1[j].alpha, t2[j].alpha);
      for (int a = 0; a < 3; ++a) c.r[a] = step(t0[j].r[a], t1[j].r[a], t2[j].r[a]);
      valid = c.alpha > 0.0 && c.r.squaredNorm() <= 1.0;
      total += c.alpha;
    }
    if (!valid) continue;
    for (size_t j = 0; j < out.size(); ++j)
      if (out[j].alpha > 0.0) {
        out[j].alpha /= total;
        if (!held(j)) set_lobe_from_resultant(out[j], kappa_max);
      }
    return out;
  }
  return {};
}

struct FixedPoint {
  int iterations = 0;           // E-steps
  bool converged = false;       // the last plain step gained less than the tolerance
  double log_likelihood = 0.0;  // of the last plain E-step
};

// EM from `mixture` until a plain step gains less than the tolerance or `budget` E-steps are spent; the result
// is the M-step of the last E-step. Without alignment, accelerated by SQUAREM (vmf_mixture.h): two plain steps,
// then the extrapolated state, kept (and stepped from) only if its log-likelihood is not below the last plain one.
FixedPoint em_to_fixed_point(std::span<const WeightedNormal> normals, std::vector<VmfComponent>& mixture,
                             const EmOptions& options, std::span<const Vec3> align_targets, int budget) {
  const bool accelerate = options.accelerate && !(options.align > 0.0 && !align_targets.empty());
  FixedPoint point;
  double previous = -std::numeric_limits<double>::infinity();
  // A plain EM step; true at a fixed point (or with the budget spent).
  const auto plain_step = [&]() {
    const EStepSums p = vmf_e_step(normals, lobe_terms(mixture));
    ++point.iterations;
    point.log_likelihood = p.log_likelihood;
    m_step(p, mixture, options, align_targets);
    point.converged = p.log_likelihood - previous < options.tolerance;
    previous = p.log_likelihood;
    return point.converged || point.iterations >= budget;
  };
  while (true) {
    const std::vector<VmfComponent> t0 = mixture;
    if (plain_step() || !accelerate) {
      if (point.converged || point.iterations >= budget) return point;
      continue;
    }
    const std::vector<VmfComponent> t1 = mixture;
    if (plain_step()) return point;
    std::vector<VmfComponent> jump = squarem_extrapolation(t0, t1, mixture, options.kappa_max);
    if (jump.empty()) continue;
    const EStepSums p = vmf_e_step(normals, lobe_terms(jump));
    ++point.iterations;
    if (p.log_likelihood >= previous) {
      m_step(p, jump, options, align_targets);
      mixture = std::move(jump);
      previous = p.log_likelihood;
      point.log_likelihood = p.log_likelihood;
    }
    if (point.iterations >= budget) return point;
  }
}

}  // namespace

double vmf_mixture_log_likelihood(std::span<const WeightedNormal> normals, const std::vector<VmfComponent>& mixture) {
  const LobeTerms t = lobe_terms(mixture);
  // The E-step's vector loop computes the log-likelihood with its sums (no live lobe: every density is 0).
  if (t.count == 0) return normals.empty() ? 0.0 : -std::numeric_limits<double>::infinity();
  return vmf_e_step(normals, t).log_likelihood;
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
  std::vector<VmfComponent> before_reseed;  // the fixed point a trial re-seed must beat
  for (int reseeds_left = int(J);;) {
    const FixedPoint point =
        em_to_fixed_point(normals, mixture, options, align_targets, options.max_iterations - report.iterations);
    report.iterations += point.iterations;
    report.converged = point.converged;
    // A trial re-seed that did not end higher by `tolerance` is undone, and the guard stops.
    if (!before_reseed.empty() && point.log_likelihood < report.log_likelihood + options.tolerance) {
      mixture = std::move(before_reseed);
      --report.reseeds;
      report.converged = true;
      break;
    }
    report.log_likelihood = point.log_likelihood;
    // The collapse guard: the weakest (smallest) live lobe gets a trial re-seed.
    size_t weakest = J, live = 0;
    for (size_t j = 0; j < J; ++j) {
      if (mixture[j].alpha <= 0.0) continue;
      ++live;
      if (weakest == J || mixture[j].alpha < mixture[weakest].alpha) weakest = j;
    }
    if (!options.reseed || weakest == J || live < 2 || reseeds_left == 0 || report.iterations >= options.max_iterations)
      break;
    before_reseed = mixture;
    mixture[weakest] = VmfComponent{};
    reseed(normals, mixture, weakest, options.kappa_max);
    --reseeds_left;
    ++report.reseeds;
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
  std::vector<double> sum(J * F, 0.0), mass(J, 0.0);
  double z[kVmfMaxLobes];
  for (size_t i = 0; i < normals.size(); ++i) {
    vmf_responsibilities(t, normals[i].n, z);
    for (size_t l = 0; l < t.count; ++l) {
      const size_t j = t.live[l];
      const double wz = normals[i].w * z[l];
      mass[j] += wz;
      for (size_t f = 0; f < F; ++f) sum[j * F + f] += wz * features[i * F + f];  // [Han07] Eq. (7.25)
    }
  }
  for (size_t j = 0; j < J; ++j)
    for (size_t f = 0; f < F; ++f) sum[j * F + f] = mass[j] > 0.0 ? sum[j * F + f] / mass[j] : 0.0;
  return sum;
}

}  // namespace mbk
