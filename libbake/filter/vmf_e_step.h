// The E-step of spherical EM for vMF mixtures ([Han07] Alg. 7.1 lines 5-7; libbake/filter/vmf_mixture.h): the
// responsibilities z_ij = alpha_j g_j(n_i) / sum_k alpha_k g_k(n_i) and the sufficient statistics the M-step needs,
// sum_i w_i z_ij and sum_i w_i z_ij n_i, with the weighted log-likelihood sum_i w_i log sum_j alpha_j g_j(n_i).
//
// In the log domain, log(alpha_j g_j(n)) = log_scale_j + kappa_j mu_j . n (log_scale_j = log(alpha_j C(kappa_j)) -
// kappa_j, so the exponent is <= 0 for every kappa), normalised by a log-sum-exp around the largest term: a term
// more than 40 nats below it is taken as 0 without evaluating exp (e^-40 ~ 4e-18 is below half an ulp of the sum,
// which is >= 1), and exp and log are the branch-free fast_exp / fast_log (libbake/core/fast_exp_log.h).
// Normals go through in blocks of four, side by side as GCC vectors, four blocks in flight at once (a lobe
// negligible for all of them needs no exp), accumulated per lane (normal i in lane i mod 4, in normal order); the
// lanes are added in lane order at the end of each kVmfSumChunk chunk, and the chunks in chunk order, so the sums
// are the same whatever the vector width, blocks in flight and thread count. A texel of more than one
// chunk splits its chunks across the threads.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "libbake/filter/vmf_mixture.h"

namespace mbk {

// The live lobes of a mixture as the E-step uses them.
struct LobeTerms {
  size_t count = 0;                  // live lobes
  size_t live[kVmfMaxLobes];         // mixture index of each live lobe
  double log_scale[kVmfMaxLobes];    // log(alpha C(kappa)) - kappa
  double kappa_mu[3][kVmfMaxLobes];  // kappa mu, by component
};
// Error(runtime_failure) for more than kVmfMaxLobes lobes.
LobeTerms lobe_terms(const std::vector<VmfComponent>& mixture);

// The sums of one E-step, indexed by mixture slot (0 for empty lobes).
struct EStepSums {
  double mass[kVmfMaxLobes] = {};       // sum_i w_i z_ij
  double moment[kVmfMaxLobes][3] = {};  // sum_i w_i z_ij n_i
  double log_likelihood = 0.0;          // sum_i w_i log sum_j alpha_j g_j(n_i)
};
// The instruction path of the E-step's vector loop: `best` is AVX2 where the processor has it, else SSE2; the two
// give bit-identical sums (vmf_e_step.cpp). Naming avx2 on a processor without it is the caller's error.
enum class VmfVectorPath { best, sse2, avx2 };
EStepSums vmf_e_step(std::span<const WeightedNormal> normals, const LobeTerms& t,
                     VmfVectorPath path = VmfVectorPath::best);

// The responsibilities of the live lobes for n into z (t.count values); returns log sum_j alpha_j g_j(n)
// (-infinity without live lobes).
double vmf_responsibilities(const LobeTerms& t, const Vec3& n, double* z);

}  // namespace mbk
