// A multi-start reference for the texel fits of vmf_mixture.h: the best of several plain spherical EM runs
// ([Han07] Alg. 7.1, [Banerjee05]) on the same normals, each started by its own weighted k-means++ seeding
// (Arthur and Vassilvitskii 2007: D^2 sampling, here on |n - mu|^2 = 2 (1 - n.mu)) followed by spherical
// k-means. Its purpose is to measure how far a fit is from a better local optimum (tests/filter and
// tests/bench/vmf_fit_bench.cpp), so it shares no code with fit_vmf_mixture beyond the vMF density: serial E- and
// M-steps written out, its own seeding, no re-seeding, no parallelism.
//
// Same model (kappa = A^-1(|r|) capped at kappa_max) without the collapse guard: a start that ends with a lobe
// on one normal simply loses to a better start, or wins when that is the better use of the lobe.
//
// Start s begins with the lobes of its k-means partition (amplitude = cluster weight, r = cluster mean
// resultant), each with its own cluster's concentration for even s, and with the pooled concentration
//   kappa_0 = A^-1(sum_c |sum_{i in c} w_i n_i|)
// for odd s (a singleton cluster then starts broad rather than as a spike). Deterministic: start s draws from
// mt19937_64(seed + s).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "libbake/filter/vmf_mixture.h"

namespace mbk {

struct VmfReferenceOptions {
  int lobes = 4;
  int starts = 3;
  int max_iterations = 5000;
  double tolerance = 1e-10;  // on the weighted mean log-likelihood
  double kappa_max = kVmfKappaMax;
  uint64_t seed = 1;
};

struct VmfReferenceFit {
  std::vector<VmfComponent> mixture;  // the best start's lobes (only the live ones)
  double log_likelihood = 0.0;        // its weighted mean log-likelihood sum_i w_i log g(n_i)
};

// Error(runtime_failure) when normals is empty or lobes < 1.
VmfReferenceFit multi_start_vmf_fit(std::span<const WeightedNormal> normals, const VmfReferenceOptions& options);

}  // namespace mbk
