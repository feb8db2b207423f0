// Loop transitions: where correction may take a loop and how it matches across one (issue 18; deviations from
// [Han08] thesis Sec. 5.2.1.2 and Eqs. 5.1-5.2, written down in docs/ARCHITECTURE.md, "Synthesis").
//
// Where: a loop edge (i, i, r), r >= 1, makes E^i_{k-r} admissible for every E^i_k, so a pixel may step to a coarser,
// smoother level of its own stack at any synthesis level and take no new detail there; level after level of a zoom
// pixels gather on the coarse levels. Here a loop is taken only from the finest level L, where the thesis forces
// correction to move on (E^i_L is never admissible): below L a pixel stays on its level or moves to another exemplar.
// The analysis searches its candidates among the same levels (a subset of the thesis' admissible levels, which the
// graph asset's validator checks).
//
// How: a loop edge (i, i, r), r >= 1, says that exemplar i seen 2^r times larger
// looks like itself: E^i_k at spacing h_k like E^i_{k-r} at spacing h_{k-r}. Unless the exemplar is self-similar,
// the two differ in local contrast: a 5 x 5 neighbourhood of a coarse-dominated texture (`gen bumps`) varies less
// over 5 texels of E_L than over 10 texels of E_{L-1}, of a fine-grained one (`gen leather`) more. Plain L2
// matching then takes, at every level of a zoom, the destination neighbourhoods nearest in contrast: for leather the
// smoothest E_{L-1} texels, and every deeper window keeps 3% of the exemplar's block variance (issue 18's
// measurement; 77% with the gain).
// So a loop transition compares neighbourhood shapes at the destination's typical contrast: the destination
// neighbourhood D enters as m_D + g (D - m_D) (m_D its mean per channel), with the gain
//   g = sqrt(c(E^i_k, h_k) / c(E^i_l, h_l)),   c = the mean over a level's texels of its 5 x 5 neighbourhoods' variance,
// a linear transfer (the thesis' r(c) = A c + b, Sec. 5.3) used for matching only: the pixel then shows the
// destination texel as it is (within an exemplar the transfer stays the identity, Sec. 5.3), so every depth keeps
// the exemplar's own contrast. Transitions between exemplars and within a level have g = 1 (plain Eq. 5.1).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace mbk {

// Whether correction may move a pixel of E^i_k (L its finest level) to E^j_l: not when it is a loop (j = i, l < k)
// taken below L. (Admissibility itself is formats/admissible_levels.h.)
inline bool loop_transition_allowed(uint32_t i, uint32_t k, uint32_t j, uint32_t l, uint32_t L) {
  return !(j == i && l < k && k < L);
}

// c of one m x m stack level (m x m x C floats) at spacing h: mean over texels of the variance (summed over channels)
// of its toroidal 5 x 5 neighbourhood at spacing h.
double neighbourhood_contrast(const float* level, uint32_t m, uint32_t channels, uint32_t h);

// g for every (exemplar, source level k, destination level l) of an exemplar's stack.
class LoopGains {
 public:
  // contrast: c of every stack level, [exemplar * levels + level].
  LoopGains(uint32_t levels, std::vector<double> contrast) : levels_(levels), contrast_(std::move(contrast)) {}
  // 1 when the transition is not a loop (other exemplar, or l >= k) or either contrast is 0.
  double gain(uint32_t source_exemplar, uint32_t k, uint32_t destination_exemplar, uint32_t l) const;

 private:
  uint32_t levels_;
  std::vector<double> contrast_;  // [exemplar * levels + level]
};

// The gains of stacks stored as [exemplars][levels][m][m][channels] floats (formats/graph_layout.h).
LoopGains loop_gains_of_stacks(const float* stacks, uint32_t exemplars, uint32_t levels, uint32_t m, uint32_t channels);

// Applies the loop transfer to a neighbourhood vector in place: v <- m_v + g (v - m_v), per channel over its 25
// samples (25 x channels values, sample-major).
void apply_loop_gain(float* neighbourhood, uint32_t channels, double gain);

}  // namespace mbk
