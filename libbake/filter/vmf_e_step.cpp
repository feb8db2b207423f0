// The vMF E-step in vectorisable blocks (see vmf_e_step.h).
#include "libbake/filter/vmf_e_step.h"

// The vector helpers are always inlined, so the AVX vector ABI GCC warns about never applies.
#pragma GCC diagnostic ignored "-Wpsabi"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <string>

#include "formats/error.h"
#include "libbake/core/fast_exp_log.h"
#include "libbake/core/parallel.h"
#include "libbake/core/vmf_lobe.h"

namespace mbk {
namespace {

// Terms this far below the largest are 0 (vmf_e_step.h); fast_exp's argument is clamped to its domain first
// (the clamped value is then discarded), so that every lane computes something finite.
constexpr double kNegligibleLog = -40.0, kExpFloor = -64.0;

// Normals go through four at a time (kLanes, the lanes of the per-lane sums), as kLanes / W GCC vectors of W
// doubles: W = 4 (one AVX register) where the processor has AVX2, else W = 2 (SSE2). Both run the same IEEE
// operations in every lane (AVX2 without FMA, so nothing is contracted) and add the lanes in the same order, so the
// sums are bit-identical on either path. Blocks (K of four normals) are in flight at once: exp and log are long
// chains of dependent operations, so independent blocks side by side keep the arithmetic units busy (K = 4 from
// 8 normals on, ~1.6x; K = 1 below); each block is still added to the lanes' sums in normal order, so the sums do
// not depend on K.
constexpr size_t kLanes = 4;
using Vector2 = double __attribute__((vector_size(16)));
using Vector2Bits = uint64_t __attribute__((vector_size(16)));
using Vector4 = double __attribute__((vector_size(32)));
using Vector4Bits = uint64_t __attribute__((vector_size(32)));

// e^(s - top), 0 when negligible; for a double or a vector.
template <typename D, typename U>
[[gnu::always_inline]] inline D relative_term(D s, D top) {
  const D d = s - top;
  return d < kNegligibleLog ? D{} : fast_exp<D, U>(d < kExpFloor ? D{} + kExpFloor : d);
}

// The E-step sums over one chunk of normals (at most kVmfSumChunk), per lane, then added in lane order.
// V: a vector of W doubles, U: of W uint64_t; B = K * kLanes / W vectors in flight.
template <typename V, typename U, size_t K>
[[gnu::always_inline]] inline void e_step_lanes(std::span<const WeightedNormal> normals, const LobeTerms& t,
                                                EStepSums& out) {
  constexpr size_t W = sizeof(V) / sizeof(double), S = kLanes / W, B = K * S;
  const size_t L = t.count, N = normals.size();
  V mass[kVmfMaxLobes][S], moment[kVmfMaxLobes][3][S], ll[S] = {};
  for (size_t l = 0; l < L; ++l)
    for (size_t v = 0; v < S; ++v) mass[l][v] = moment[l][0][v] = moment[l][1][v] = moment[l][2][v] = V{};
  for (size_t first = 0; first < N; first += K * kLanes) {
    // Vector v holds normals first + W v .. first + W v + W - 1; it adds to lane group v % S.
    V n[3][B] = {}, w[B] = {}, s[kVmfMaxLobes][B], top[B] = {}, sum[B] = {};
    for (size_t b = 0; b < K * kLanes; ++b) {
      const bool in = first + b < N;  // lanes past the end: a zero-weight +z normal, which adds 0
      const WeightedNormal& wn = normals[in ? first + b : N - 1];
      for (int a = 0; a < 3; ++a) n[a][b / W][b % W] = in ? wn.n[a] : a == 2 ? 1.0 : 0.0;
      w[b / W][b % W] = in ? wn.w : 0.0;
    }
    for (size_t l = 0; l < L; ++l)
      for (size_t v = 0; v < B; ++v) {
        s[l][v] = t.log_scale[l] + t.kappa_mu[0][l] * n[0][v] + t.kappa_mu[1][l] * n[1][v] + t.kappa_mu[2][l] * n[2][v];
        top[v] = l == 0 ? s[l][v] : (s[l][v] > top[v] ? s[l][v] : top[v]);
      }
    for (size_t l = 0; l < L; ++l) {
      // A lobe negligible in every lane of the blocks in flight (common at high kappa) needs no exp; the
      // negligible terms are 0 either way.
      bool all = true;
      for (size_t v = 0; v < B; ++v) {
        const auto negligible = s[l][v] - top[v] < kNegligibleLog;
        for (size_t e = 0; e < W; ++e) all = all && negligible[e];
      }
      for (size_t v = 0; v < B; ++v) {
        s[l][v] = all ? V{} : relative_term<V, U>(s[l][v], top[v]);
        sum[v] += s[l][v];
      }
    }
    V log_sum[B];
    for (size_t v = 0; v < B; ++v) log_sum[v] = fast_log<V, U>(sum[v]);
    for (size_t v = 0; v < B; ++v) {
      const size_t g = v % S;
      ll[g] += w[v] * (top[v] + log_sum[v]);
      const V q = w[v] / sum[v];
      for (size_t l = 0; l < L; ++l) {
        const V wz = s[l][v] * q;
        mass[l][g] += wz;
        for (int a = 0; a < 3; ++a) moment[l][a][g] += wz * n[a][v];
      }
    }
  }
  for (size_t b = 0; b < kLanes; ++b) {
    out.log_likelihood += ll[b / W][b % W];
    for (size_t l = 0; l < L; ++l) {
      out.mass[t.live[l]] += mass[l][b / W][b % W];
      for (int a = 0; a < 3; ++a) out.moment[t.live[l]][a] += moment[l][a][b / W][b % W];
    }
  }
}

void e_step_chunk_sse2(std::span<const WeightedNormal> normals, const LobeTerms& t, EStepSums& out) {
  if (normals.size() < 2 * kLanes) return e_step_lanes<Vector2, Vector2Bits, 1>(normals, t, out);
  e_step_lanes<Vector2, Vector2Bits, 4>(normals, t, out);
}

[[gnu::target("avx2")]] void e_step_chunk_avx2(std::span<const WeightedNormal> normals, const LobeTerms& t,
                                               EStepSums& out) {
  if (normals.size() < 2 * kLanes) return e_step_lanes<Vector4, Vector4Bits, 1>(normals, t, out);
  e_step_lanes<Vector4, Vector4Bits, 4>(normals, t, out);
}

using ChunkFunction = void (*)(std::span<const WeightedNormal>, const LobeTerms&, EStepSums&);

ChunkFunction chunk_function(VmfVectorPath path) {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (path == VmfVectorPath::best) path = avx2 ? VmfVectorPath::avx2 : VmfVectorPath::sse2;
  return path == VmfVectorPath::avx2 ? e_step_chunk_avx2 : e_step_chunk_sse2;
}

}  // namespace

LobeTerms lobe_terms(const std::vector<VmfComponent>& mixture) {
  if (mixture.size() > size_t(kVmfMaxLobes))
    throw Error(ExitCode::runtime_failure, "internal: vMF mixture of " + std::to_string(mixture.size()) + " lobes");
  LobeTerms t;
  for (size_t j = 0; j < mixture.size(); ++j) {
    const VmfComponent& c = mixture[j];
    if (!(c.alpha > 0.0)) continue;
    t.live[t.count] = j;
    t.log_scale[t.count] = std::log(c.alpha) + vmf_log_density(c.kappa, 1.0) - c.kappa;
    for (int a = 0; a < 3; ++a) t.kappa_mu[a][t.count] = c.kappa * c.mu[a];
    ++t.count;
  }
  return t;
}

EStepSums vmf_e_step(std::span<const WeightedNormal> normals, const LobeTerms& t, VmfVectorPath path) {
  const ChunkFunction e_step_chunk = chunk_function(path);
  const size_t chunks = (normals.size() + kVmfSumChunk - 1) / kVmfSumChunk;
  const auto chunk = [&](size_t c) {
    return normals.subspan(c * kVmfSumChunk, std::min(kVmfSumChunk, normals.size() - c * kVmfSumChunk));
  };
  EStepSums total;
  if (chunks <= 1) {
    e_step_chunk(normals, t, total);
    return total;
  }
  std::vector<EStepSums> partials(chunks);
  parallel_for(0, int64_t(chunks), [&](int64_t c) { e_step_chunk(chunk(size_t(c)), t, partials[size_t(c)]); });
  for (const EStepSums& p : partials) {
    total.log_likelihood += p.log_likelihood;
    for (size_t l = 0; l < t.count; ++l) {
      const size_t j = t.live[l];
      total.mass[j] += p.mass[j];
      for (int a = 0; a < 3; ++a) total.moment[j][a] += p.moment[j][a];
    }
  }
  return total;
}

double vmf_responsibilities(const LobeTerms& t, const Vec3& n, double* z) {
  double top = -std::numeric_limits<double>::infinity(), sum = 0.0;
  for (size_t l = 0; l < t.count; ++l) {
    z[l] = t.log_scale[l] + t.kappa_mu[0][l] * n[0] + t.kappa_mu[1][l] * n[1] + t.kappa_mu[2][l] * n[2];
    top = std::max(top, z[l]);
  }
  if (t.count == 0) return top;
  for (size_t l = 0; l < t.count; ++l) {
    z[l] = relative_term<double, uint64_t>(z[l], top);
    sum += z[l];
  }
  const double inverse = 1.0 / sum;
  for (size_t l = 0; l < t.count; ++l) z[l] *= inverse;
  return top + fast_log(sum);
}

}  // namespace mbk
