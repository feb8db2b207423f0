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

constexpr size_t kChunk = 1 << 14;

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
    z[j] = std::exp(z[j] - top);  // in [0, 1]; exactly 1 for the largest
    sum += z[j];
  }
  for (size_t j = 0; j < J; ++j) z[j] /= sum;
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

}  // namespace

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
    if (p.log_likelihood - previous < options.tolerance) {
      report.converged = true;
      break;
    }
    previous = p.log_likelihood;
  }
  // The amplitudes of the live lobes sum to the mass of the last E-step (1 up to rounding); renormalise so
  // that stored amplitudes sum to 1.
  double total = 0.0;
  for (const VmfComponent& c : mixture) total += c.alpha;
  for (VmfComponent& c : mixture) c.alpha /= total;
  return report;
}

std::vector<VmfComponent> farthest_apart_seeds(std::span<const VmfComponent> candidates, int J) {
  // Smallest 1 - cos between two chosen seeds: closer lobes count as the same direction.
  constexpr double kDistinctDirection = 1e-12;
  std::vector<VmfComponent> seeds(static_cast<size_t>(J));
  if (candidates.empty()) return seeds;
  size_t first = 0;
  for (size_t c = 1; c < candidates.size(); ++c)
    if (candidates[c].alpha > candidates[first].alpha) first = c;
  std::vector<double> distance(candidates.size(), 2.0);  // smallest 1 - cos to a chosen seed
  size_t chosen = 0, next = first;
  while (chosen < size_t(J)) {
    seeds[chosen++] = candidates[next];
    for (size_t c = 0; c < candidates.size(); ++c)
      distance[c] = std::min(distance[c], 1.0 - candidates[c].mu.dot(candidates[next].mu));
    next = size_t(std::max_element(distance.begin(), distance.end()) - distance.begin());
    if (distance[next] <= kDistinctDirection) break;
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
