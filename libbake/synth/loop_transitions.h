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
// How: a loop edge (i, i, r), r >= 1, says that exemplar i seen 2^r times larger looks like itself: E^i_k at spacing
// h_k like E^i_{k-r} at spacing h_{k-r}. Unless the exemplar is self-similar, the two differ in local contrast, and
// plain L2 matching (Eqs. 5.1, 5.2) prefers, among imperfect matches, the destination neighbourhoods of least
// contrast (a low-contrast guess is the smaller error against anything it does not match): at every level of a
// zoom the pixels move to flatter parts of the exemplar, and a flat region, once there, is its own best match.
// So a loop destination neighbourhood D enters the comparison at the source level's typical contrast:
//   D' = m_D + sqrt(c_k / v_D) (D - m_D),
// m_D its mean per channel, v_D its variance (over the 25 samples, summed over channels; D unchanged when v_D is below
// 1e-6 c_k, flat to rounding), c_k the
// mean of v over the source level E^i_k's own neighbourhoods at spacing h_k: a linear transfer (the thesis'
// r(c) = A c + b, Sec. 5.3) used for matching only: the pixel shows the destination texel at its own contrast, so
// every depth keeps the exemplar's.
// And a loop transition carries a constant-offset transfer b = mean(source - destination) like an edge between
// exemplars (Sec. 5.3; the thesis takes b = 0 within an exemplar, consistent by definition): a loop over a
// non-self-similar exemplar is inconsistent. Without it a magnified smooth slope of a coarse-dominated exemplar
// (`gen bumps`) can only be matched by neighbourhoods of the same mean normal, which are the exemplar's own smooth
// slopes, and it stays smooth at every depth; with it any detail can sit on the slope, the slope's tilt carried by
// the transfer (issue 18: "the exemplar's finest detail on top of magnified coarser content"). The analysis ranks a
// pool that holds a loop level by the error left after that offset (mean-removed neighbourhoods).
// And the offsets loops add fade: a pixel's children keep kLoopOffsetKept (1/2) of the share of its cumulative
// transfer R that loop transitions added (transfers between exemplars are kept whole, as the thesis). In a self-loop
// zoom every pixel takes a loop at every level, and each offset is the difference between two scales' local means
// of the exemplar, an independent band: summed, R is a random walk (measured on `gen bumps`: mean |R| 0.16 at the
// exemplar's scale, 0.9 fourteen levels deeper, windows' mean normals tilted by up to 0.6, and the renormalised
// detail squashed to 0.46x the exemplar's block variance: issue 18). A surface whose every octave carries the
// exemplar's slopes has unbounded slope variance; a zoom that keeps the exemplar's statistics at every depth must
// forget old tilts. Halving per level (per octave) holds R's variance at 4/3 of one level's offsets' and each
// window's mean normal within 0.05 of the exemplar's.
// Transitions between exemplars and within a level are matched as the thesis does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace mbk {

// The share of the offsets loop transitions added that a pixel's children keep (per synthesis level).
inline constexpr double kLoopOffsetKept = 0.5;

// Whether correction may move a pixel of E^i_k (L its finest level) to E^j_l: not when it is a loop (j = i, l < k)
// taken below L. (Admissibility itself is formats/admissible_levels.h.)
inline bool loop_transition_allowed(uint32_t i, uint32_t k, uint32_t j, uint32_t l, uint32_t L) {
  return !(j == i && l < k && k < L);
}

// c of one m x m stack level (m x m x C floats) at spacing h: mean over texels of the variance (summed over channels)
// of its toroidal 5 x 5 neighbourhood at spacing h.
double neighbourhood_contrast(const float* level, uint32_t m, uint32_t channels, uint32_t h);

// c of every stack level, and the contrast a transition's destination neighbourhoods are brought to.
class LoopContrast {
 public:
  // contrast: c of every stack level, [exemplar * levels + level].
  LoopContrast(uint32_t levels, std::vector<double> contrast) : levels_(levels), contrast_(std::move(contrast)) {}
  // c_k for a loop transition E^i_k -> E^i_l (l < k); 0 (match as the thesis) otherwise.
  double target(uint32_t source_exemplar, uint32_t k, uint32_t destination_exemplar, uint32_t l) const {
    return source_exemplar == destination_exemplar && l < k ? contrast_[size_t(source_exemplar) * levels_ + k] : 0.0;
  }

 private:
  uint32_t levels_;
  std::vector<double> contrast_;
};

// The contrasts of stacks stored as [exemplars][levels][m][m][channels] floats (formats/graph_layout.h).
LoopContrast loop_contrast_of_stacks(const float* stacks, uint32_t exemplars, uint32_t levels, uint32_t m,
                                     uint32_t channels);

// v <- v - m_v per channel, in place (25 x channels values, sample-major).
void remove_neighbourhood_mean(float* neighbourhood, uint32_t channels);

// D <- m_D + sqrt(target / v_D) (D - m_D) in place (25 x channels values, sample-major); unchanged when target is 0
// or v_D <= 1e-6 target.
void bring_to_contrast(float* neighbourhood, uint32_t channels, double target);

}  // namespace mbk
