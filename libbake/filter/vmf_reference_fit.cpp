// Multi-start reference EM for vMF mixtures (see vmf_reference_fit.h).
#include "libbake/filter/vmf_reference_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "formats/error.h"
#include "libbake/core/vmf_lobe.h"

namespace mbk {
namespace {

// A uniform double in [0, 1) from 53 random bits (the same on every standard library).
double uniform01(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

// An index drawn with probability proportional to mass[i] (sum > 0).
size_t draw(std::mt19937_64& rng, const std::vector<double>& mass) {
  double total = 0.0;
  for (double m : mass) total += m;
  double u = uniform01(rng) * total;
  for (size_t i = 0; i < mass.size(); ++i) {
    if (u < mass[i]) return i;
    u -= mass[i];
  }
  for (size_t i = mass.size(); i-- > 0;)
    if (mass[i] > 0.0) return i;
  return 0;
}

// Weighted k-means++ directions, then spherical k-means; lobes with their cluster's concentration, or the
// pooled one.
std::vector<VmfComponent> kmeans_start(std::span<const WeightedNormal> normals, int J, double kappa_max,
                                       bool pooled_kappa, std::mt19937_64& rng) {
  const size_t N = normals.size();
  std::vector<double> mass(N), distance(N, std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < N; ++i) mass[i] = normals[i].w;
  std::vector<Vec3> centres = {normals[draw(rng, mass)].n};
  while (centres.size() < size_t(J)) {
    double total = 0.0;
    for (size_t i = 0; i < N; ++i) {
      distance[i] = std::min(distance[i], std::max(0.0, 1.0 - normals[i].n.dot(centres.back())));
      mass[i] = normals[i].w * distance[i];
      total += mass[i];
    }
    if (!(total > 0.0)) break;  // every normal coincides with a centre
    centres.push_back(normals[draw(rng, mass)].n);
  }
  std::vector<size_t> label(N);
  std::vector<Vec3> sum(centres.size());
  std::vector<double> weight(centres.size());
  for (int round = 0; round < 10; ++round) {
    std::fill(sum.begin(), sum.end(), Vec3::Zero());
    std::fill(weight.begin(), weight.end(), 0.0);
    for (size_t i = 0; i < N; ++i) {
      size_t best = 0;
      for (size_t c = 1; c < centres.size(); ++c)
        if (normals[i].n.dot(centres[c]) > normals[i].n.dot(centres[best])) best = c;
      label[i] = best;
      sum[best] += normals[i].w * normals[i].n;
      weight[best] += normals[i].w;
    }
    for (size_t c = 0; c < centres.size(); ++c)
      if (sum[c].norm() > 0.0) centres[c] = sum[c].normalized();
  }
  double pooled = 0.0, total = 0.0;
  for (size_t c = 0; c < centres.size(); ++c) pooled += sum[c].norm(), total += weight[c];
  const double kappa = vmf_kappa_from_mean_length(pooled / total, kappa_max);
  std::vector<VmfComponent> lobes;
  for (size_t c = 0; c < centres.size(); ++c) {
    if (!(weight[c] > 0.0)) continue;
    VmfComponent l;
    l.alpha = weight[c] / total;
    l.kappa = pooled_kappa ? kappa : vmf_kappa_from_mean_length(sum[c].norm() / weight[c], kappa_max);
    l.mu = centres[c];
    lobes.push_back(l);
  }
  return lobes;
}

// Plain EM (serial) to a fixed point; returns the mean log-likelihood of the final lobes (that of the last
// E-step: the loop stops before its M-step).
double plain_em(std::span<const WeightedNormal> normals, std::vector<VmfComponent>& lobes,
                const VmfReferenceOptions& o) {
  const size_t J = lobes.size();
  std::vector<double> log_term(J);
  double previous = -std::numeric_limits<double>::infinity(), ll = previous;
  for (int it = 0; it < o.max_iterations; ++it) {
    std::vector<double> mass(J, 0.0);
    std::vector<Vec3> moment(J, Vec3::Zero());
    ll = 0.0;
    for (const WeightedNormal& wn : normals) {
      double top = -std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < J; ++j) {
        log_term[j] = lobes[j].alpha > 0.0
                          ? std::log(lobes[j].alpha) + vmf_log_density(lobes[j].kappa, lobes[j].mu.dot(wn.n))
                          : -std::numeric_limits<double>::infinity();
        top = std::max(top, log_term[j]);
      }
      double s = 0.0;
      for (size_t j = 0; j < J; ++j) s += std::exp(log_term[j] - top);
      ll += wn.w * (top + std::log(s));
      for (size_t j = 0; j < J; ++j) {
        const double z = std::exp(log_term[j] - top) / s;
        mass[j] += wn.w * z;
        moment[j] += wn.w * z * wn.n;
      }
    }
    if (ll - previous < o.tolerance || it + 1 == o.max_iterations) break;
    previous = ll;
    double total = 0.0;
    for (size_t j = 0; j < J; ++j) total += mass[j];
    for (size_t j = 0; j < J; ++j) {
      lobes[j].alpha = mass[j] / total;
      lobes[j].r = mass[j] > 0.0 ? Vec3(moment[j] / mass[j]) : Vec3::Zero();
      set_lobe_from_resultant(lobes[j], o.kappa_max);
    }
  }
  return ll;
}

}  // namespace

VmfReferenceFit multi_start_vmf_fit(std::span<const WeightedNormal> normals, const VmfReferenceOptions& options) {
  if (normals.empty() || options.lobes < 1)
    throw Error(ExitCode::runtime_failure, "internal: reference vMF fit without normals or lobes");
  VmfReferenceFit best;
  best.log_likelihood = -std::numeric_limits<double>::infinity();
  for (int s = 0; s < options.starts; ++s) {
    std::mt19937_64 rng(options.seed + uint64_t(s));
    std::vector<VmfComponent> lobes = kmeans_start(normals, options.lobes, options.kappa_max, s % 2 == 1, rng);
    const double ll = plain_em(normals, lobes, options);
    std::erase_if(lobes, [](const VmfComponent& c) { return !(c.alpha > 0.0); });
    if (ll > best.log_likelihood) best = {std::move(lobes), ll};
  }
  return best;
}

}  // namespace mbk
