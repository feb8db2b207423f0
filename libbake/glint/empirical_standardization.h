// The standardization transform G of one channel of an example and its inverse, exactly, before any sampling
// into tables ([Heitz18] Sec. 3; [Wang20] Eq. 6: I_h = G^-1[G(I)_v]). Conventions in glint_technique.h.
//
// Let the N values of the channel have the distinct values u_1 < ... < u_K with counts c_1 .. c_K. The MID-RANK
// of u_k is r_k = c_1 + ... + c_{k-1} + c_k / 2 (equal values share one rank, the middle of their run), and its
// empirical CDF value F_k = r_k / N lies strictly inside (0, 1). Between consecutive distinct values F is linear:
//
//     F(x) = F_k + (x - u_k) / (u_{k+1} - u_k) * (F_{k+1} - F_k)       for u_k <= x <= u_{k+1},
//
// and F = F_1 below u_1, F = F_K above u_K. Then
//
//     +-------------------------------------------------------------+
//     |  G(x) = Phi^-1(F(x)),        G^-1(z) = F^-1(Phi(z)),        |
//     +-------------------------------------------------------------+
//
// with F^-1 linear in F between the same nodes and clamped to [u_1, u_K]. G is continuous and strictly increasing
// on [u_1, u_K] and G^-1 is its exact inverse on [G(u_1), G(u_K)], so G^-1(G(x)) = x up to rounding. Below G(u_1)
// and above G(u_K), G^-1 is the constant u_1 or u_K: the Gaussian mass there, (c_1 + c_K) / (2N), is where a
// blend is clipped to the example's extremes. A constant channel (K = 1) has F = 1/2, G = 0 and G^-1 = u_1
// everywhere (its clipped mass is 1). N(0, 1) is the standard normal (standard_normal.h).
//
// (A C^1 monotone interpolant between the nodes, Steffen's, was tried instead of the linear one: it lowered the
// inverse table's own interpolation error only on maps with very few distinct values (panels, 23 per channel:
// 1.4e-3 -> 4.7e-4 at 4096 samples, 512^2), was slightly worse on the others, and changed nothing the round trip
// through the tables shows; the linear interpolant is kept.)
//
// Precision: ranks are kept as the integers 2 r_k, and each tail is evaluated through its own mass (F below 1/2,
// 1 - F above), so z keeps full relative precision at both ends.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace mbk {

class EmpiricalStandardization {
 public:
  // Sorts `values` in place (-0 counts as +0). Throws Error(runtime_failure) when `values` is empty, holds a
  // non-finite value (normal maps never do: libbake/image/normal_map.h) or more than 2^31 - 1 values.
  explicit EmpiricalStandardization(std::vector<float> values);

  double min() const { return values_.front(); }
  double max() const { return values_.back(); }
  size_t distinct_values() const { return values_.size(); }
  // u_1 < ... < u_K.
  std::span<const float> distinct() const { return values_; }
  size_t count() const { return size_t(twice_count_ / 2); }  // N
  // The distinct values u_k whose count c_k is at least `min_count` (the heavy runs, the atoms of F), ascending.
  std::vector<float> values_counted_at_least(uint64_t min_count) const;
  // G(min) = Phi^-1(c_1 / 2N) and G(max) = -Phi^-1(c_K / 2N): where G^-1 stops varying. The Gaussian mass beyond
  // them, (c_1 + c_K) / (2N), is the channel's clipped tail mass (1 for a constant channel: both are 0).
  double gaussian_min() const { return gaussian_min_; }
  double gaussian_max() const { return gaussian_max_; }

  // G(x), clamped outside [min, max] (NaN gives G(min)).
  double forward(double x) const;
  // G^-1(z), clamped outside [G(min), G(max)] (NaN gives min).
  double inverse(double z) const;

 private:
  double gaussian_of_twice_rank(double twice_rank) const;
  // 8 bytes per distinct value: a 16384^2 map of distinct values needs 2 GiB per channel.
  std::vector<float> values_;         // u_1 < ... < u_K (float inputs: exact)
  std::vector<uint32_t> twice_rank_;  // 2 r_k = 2 (c_1 + ... + c_{k-1}) + c_k, strictly increasing, < 2^32
  uint64_t twice_count_ = 0;          // 2 N
  double gaussian_min_ = 0.0, gaussian_max_ = 0.0;
};

}  // namespace mbk
