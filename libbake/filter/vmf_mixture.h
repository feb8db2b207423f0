// Fitting mixtures of von Mises-Fisher lobes to the normals under a texel by spherical EM: [Han07] Sec. 7.6.1,
// Alg. 7.1 (after Banerjee et al. 2005), with the coherence term of Sec. 7.6.4.2 (Eq. 7.26) and the feature
// average of Sec. 7.6.4.1 (Eq. 7.25).
//
// The NDF of a texel is sum_i w_i delta(n - n_i) (w_i the area weights of formats/mip_levels.h, summing to 1).
// The mixture is g(n) = sum_j alpha_j vMF(n; kappa_j, mu_j) (libbake/core/vmf_lobe.h). One EM iteration:
//   E-step  z_ij = alpha_j g_j(n_i) / sum_k alpha_k g_k(n_i), in the log domain: log alpha_j + log g_j(n_i) is
//           at most log(alpha_j kappa_j / (2 pi (1 - e^-2k))) (the exponent kappa (mu.n - 1) <= 0), and the
//           normaliser is a log-sum-exp around the largest term, so nothing overflows for any kappa.
//   M-step  alpha_j = sum_i w_i z_ij;  r_j = sum_i w_i z_ij n_i / alpha_j;  kappa_j = A^-1(|r_j|) by the
//           guarded Newton solve (not Alg. 7.1 line 12's closed form, which is up to ~5% off), capped at
//           kappa_max (|r_j| -> 1 when the lobe's normals are identical);
//           mu_j = normalize(r_j + C sum_k alpha_jk mu_jk) (Eq. 7.26; C = 0 gives Alg. 7.1 line 13).
// Stopping: when the weighted mean log-likelihood sum_i w_i log g(n_i) rises by less than `tolerance` in a plain
// EM step (or after max_iterations E-steps). EM never lowers it for C = 0; with C > 0 a fall also stops it.
// The E-step and its log-sum-exp are in vmf_e_step.h.
// Acceleration (deviation [Han07]; C = 0 only): SQUAREM (Varadhan and Roland 2008, scheme S3). From theta_0, two
// plain steps give theta_1 = M(theta_0), theta_2 = M(theta_1) in the parameters (alpha_j, r_j); the jump
// theta_0 - 2 s d + s^2 v (d = theta_1 - theta_0, v = theta_2 - 2 theta_1 + theta_0, s = -|d| / |v|, moved
// halfway to -1 while a lobe would get alpha <= 0 or |r| > 1) is evaluated by an E-step and kept, with its
// M-step, only if its log-likelihood is not below theta_1's; otherwise EM goes on from theta_2. So the
// log-likelihood never falls, the fixed points are those of plain EM, and slow (linear) EM convergence takes
// about half the E-steps (VmfMixture.AccelerationReachesThePlainFixedPointSooner). Lobes at the kappa cap
// (atoms of identical normals) keep theta_2's parameters: a jump along their r moves them off the atom, and
// on piecewise-constant maps it cost whole atoms their lobes.
// Normals may be chunk means (|n| < 1, vmf_normal_chunks.h): the E- and M-steps then run chunked EM unchanged.
// Empty lobes: a lobe whose amplitude falls below kEmptyAmplitude is emptied (alpha = 0, r = 0) and takes no
// further part; a texel with fewer distinct normals than lobes keeps the extra lobes empty (test:
// VmfMixture.MoreLobesThanDistinctNormals).
//
// Collapse guard (deviation [Han07], whose Alg. 7.1 has none). A lobe whose normals are one direction is a
// fixed point of EM at the kappa cap: r_j = n_i gives kappa_max, and its responsibility for any other normal
// at angle theta, ~exp(-kappa_max theta^2 / 2), is 0, so it never grows. Farthest-apart seeding picks outlying
// normals (k-center is an outlier criterion) and child lobes at the cap, so coarse texels ended with lobes of
// amplitude ~1/N on one outlying normal each. The guard is neither a minimum weight nor a kappa prior: both
// change the objective, and on piecewise-constant and 8-bit maps a small lobe at the cap on a cluster of
// identical normals is often the best use of its slot (a prior would also lower kappa below the cap for
// identical normals, which VmfMixture.IdenticalNormalsCapKappa keeps at kappa_max). It is an accept-if-better
// re-seed of the weakest lobe (as in split-and-merge EM, Ueda et al. 2000): at a fixed point of EM (the
// log-likelihood gain below `tolerance`, or the budget spent) the live lobe of smallest amplitude is removed and
// re-seeded where the rest of the mixture explains the normals worst, and EM continues; at the next fixed point
// the trial is kept if the log-likelihood rose by at least `tolerance`, otherwise it is undone and the guard
// stops. At most J trials per fit, and only with iterations left. The re-seed: with p(n_i) the density of the
// remaining lobes, the candidates are the normals at weight quantiles 0, 1/16, ..., 15/16 of the normals sorted
// by increasing p (the normal at q is the one whose span of cumulative weight holds q, so a heavy chunk can be
// a candidate; the first is the worst-explained normal; chunk means are normalised), each with kappa_s, the pooled
// concentration of the live lobes A^-1(sum_l alpha_l |r_l| / sum_l alpha_l), or with kappa_max (a cluster of identical
// normals); the pair that maximises the gain of a lobe of amplitude a = 1/J (the others scaled by 1 - a)
//     G(c, kappa) = sum_i w_i log(1 - a + a g(n_i; kappa, n_c) / p(n_i))
// is taken. So the guarded fit never ends below the unguarded one from the same start, a lobe on an isolated
// outlier is moved to where it explains more (VmfMixture.OutlierGetsNoLobe), and a small lobe that is the
// better use of its slot stays (VmfMixture.GuardNeverLowersTheLikelihood). The stored state is always that of
// an M-step.
// Deterministic: sums over normals run in fixed chunks whose partial sums are added in chunk order, so the
// result is the same whatever the thread count, and large texels are split across threads.
#pragma once

#include <span>
#include <vector>

#include "libbake/core/eigen.h"

namespace mbk {

// kappa cap: identical normals (|r| = 1) get this concentration, an angular spread of ~1e-3 rad.
inline constexpr double kVmfKappaMax = 1e6;
// Amplitude below which a lobe is emptied.
inline constexpr double kEmptyAmplitude = 1e-9;
// Normals per chunk of the E-step's sums (the unit of its parallel split; partial sums are added in chunk order).
inline constexpr size_t kVmfSumChunk = size_t(1) << 14;
// Lobes per mixture at most.
inline constexpr int kVmfMaxLobes = 16;
// EM iterations at most per fit by default.
inline constexpr int kVmfDefaultMaxIterations = 1000;

struct VmfComponent {
  double alpha = 0.0;       // amplitude; 0 = empty lobe
  Vec3 r = Vec3::Zero();    // mean resultant vector: |r| = A(kappa), r / |r| = mu (before alignment)
  double kappa = 0.0;       // A^-1(|r|), capped
  Vec3 mu = Vec3::UnitZ();  // lobe direction (r / |r|, or the aligned direction of Eq. 7.26)
};

struct WeightedNormal {
  Vec3 n;
  double w;  // weights of a texel's normals sum to 1
};

struct EmOptions {
  double tolerance = 1e-6;  // on the weighted mean log-likelihood (nats per normal)
  int max_iterations = kVmfDefaultMaxIterations;
  double kappa_max = kVmfKappaMax;
  double align = 0.0;      // C of Eq. 7.26
  bool reseed = true;      // the collapse guard (false: plain EM)
  bool accelerate = true;  // SQUAREM steps (without alignment)
};

struct EmReport {
  int iterations = 0;
  bool converged = false;
  double log_likelihood = 0.0;  // weighted mean, after the last E-step
  int reseeds = 0;              // trial re-seeds of the collapse guard that were kept
};

// Runs EM from the given start (non-empty lobes need alpha > 0 and unit mu; their kappa is used as given).
// `align_targets` is empty or one vector per lobe: sum over neighbours of alpha_jk mu_jk (Eq. 7.26).
// Error(runtime_failure) when no lobe is non-empty or normals is empty.
EmReport fit_vmf_mixture(std::span<const WeightedNormal> normals, std::vector<VmfComponent>& mixture,
                         const EmOptions& options, std::span<const Vec3> align_targets = {});

// Eq. (7.25): per lobe, the responsibility-weighted mean of per-normal features (feature_count values per
// normal, row i at features[i * feature_count]), from one E-step with the final mixture. Empty lobes get 0.
std::vector<double> lobe_features(std::span<const WeightedNormal> normals, std::span<const float> features,
                                  int feature_count, const std::vector<VmfComponent>& mixture);

// Hochbaum-Shmoys farthest-point seeding ([Han07] Sec. 7.6.1): first the candidate of largest amplitude (the
// first of equals), then repeatedly the one whose smallest 1 - mu.mu_s to the chosen seeds is largest, until J
// are chosen or every remaining candidate coincides (1 - cos <= 1e-12) with a chosen one. Returns J lobes: the
// chosen ones (their kappa and mu, amplitude 1 / count) then empty ones.
// SeedRule::mass_weighted (deviation [Han07]) picks the largest alpha_c (1 - mu_c.mu_s) instead after the first,
// among the candidates that do not coincide with a chosen one: pure farthest-point seeding is drawn to outlying
// lobes of negligible mass (k-center is an outlier criterion), the weighted rule to heavy distinct ones.
enum class SeedRule { farthest, mass_weighted };
std::vector<VmfComponent> farthest_apart_seeds(std::span<const VmfComponent> candidates, int J,
                                               SeedRule rule = SeedRule::farthest);

// The weighted mean log-likelihood sum_i w_i log g(n_i) of a mixture (its live lobes; amplitudes as given).
double vmf_mixture_log_likelihood(std::span<const WeightedNormal> normals, const std::vector<VmfComponent>& mixture);

// Sets kappa = A^-1(|r|) (capped) and mu = r / |r| (mu = +z for r = 0).
void set_lobe_from_resultant(VmfComponent& lobe, double kappa_max);

}  // namespace mbk
