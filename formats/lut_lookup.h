// Looking up a standardization table: THE lookup convention of asset kind `lut` (formats/lut_layout.h). This is
// what the evaluator calls (histogram-preserving blending, [Wang20] Eq. 6, and its Jacobian, [Wang20] appendix):
// it depends on nothing but the knots, never on the baker, so a shader port needs these few lines and the
// asset's sections.
//
// A map through knots (k_0, v_0) .. (k_{M-1}, v_{M-1}), keys and values strictly increasing. For k_0 <= x <= k_{M-1}
// and M >= 2, with i the largest index <= M - 2 such that k_i <= x:
//
//     d_i = (v_{i+1} - v_i) / (k_{i+1} - k_i),     value = v_i + (x - k_i) d_i,     derivative = d_i,
//
// all in double from the stored floats (d_i computed once per segment); so on [k_i, k_{i+1}) the derivative is
// that segment's slope, and at k_{M-1}
// it is the last segment's. Below k_0 (and for NaN) the value is v_0, above k_{M-1} it is v_{M-1}, derivative 0
// (the clamped map is flat there); with one knot the map is the constant v_0. The forward table G_T reads a
// channel's knots as (x, z), the inverse G^-1_T as (z, x).
//
// Finding i: any search gives the same i. Ours is O(1) on average: a uniform index of 4 (M - 1) cells over
// [k_0, k_{M-1}] stores, per cell, the knots that can bracket an x falling in it (KnotInterpolant below).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace mbk {

struct LutSample {
  double value = 0.0;
  double derivative = 0.0;
};

class KnotInterpolant {
 public:
  KnotInterpolant() = default;
  // keys.size() == values.size() >= 1. Unvalidated knots (not increasing) give clamped, in-bounds lookups.
  KnotInterpolant(std::span<const float> keys, std::span<const float> values);

  LutSample operator()(double x) const;
  std::span<const float> keys() const { return keys_; }
  std::span<const float> values() const { return values_; }

 private:
  size_t cell_of(double x) const;
  std::vector<float> keys_, values_;
  std::vector<double> slopes_;  // d_i, M - 1 of them
  // Cell c holds x with cell_of(x) == c; the knot index that brackets such an x lies in [first_[c], first_[c + 1]].
  std::vector<uint32_t> first_;
  double cell_scale_ = 0.0;  // cells per unit of key
};

}  // namespace mbk
