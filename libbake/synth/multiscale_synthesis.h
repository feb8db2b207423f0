// Parallel multiscale synthesis from an analysed exemplar graph ([Han08] thesis Sec. 5.2.2, after Lefebvre &
// Hoppe 2005), windows of any level at any position, deterministic and independent of how the plane is tiled.
//
// Synthesis levels t = 0..T hold, per pixel p of the infinite plane, a texel pointer (exemplar i, stack level k,
// texel u) and a cumulative constant-offset transfer R (Sec. 5.3); the pixel's colour is E^i_k[u] + R.
//   level 0: every pixel points at texel (0, 0) of the root's level 0 (the exemplar's mean), R = 0;
//   upsampling (Sec. 5.2.2.1): child 2p + D + (1/2, 1/2), D in {-1/2, +1/2}^2, gets (i, k + 1, u + floor(h_{k+1} D)
//     mod m) (Deviation [Han08]: the thesis writes h_k, the parent's spacing; h_{k+1}, as Lefebvre & Hoppe, puts
//     the children one child texel apart, which is what keeps coherent patches coherent: test
//     MultiscaleSynthesis.SelfLoopZoomTenLevelsDeepStaysCoherent); a pixel stuck at the finest level L (its exemplar
//     has no admissible level there, so correction cannot move it on) passes its texel to its four children and is not
//     jittered: it magnifies its exemplar (nearest texel); R is bilinear in the four nearest parents' R (the thesis:
//     piecewise-constant inheritance blocks), less half the share of it that loop transitions added (that share
//     fades: loop_transitions.h);
//   jitter (Sec. 5.2.2.2): u += floor(h_k H(p) r_t + (1/2, 1/2)) mod m, H a PCG hash of (seed, t, p) into [-1, 1]^2,
//     r_t the level's randomness (options.jitter[t], the last value repeating);
//   correction (Sec. 5.2.2.3, Eq. 5.1 with k-coherence, Eq. 5.3): `passes` passes of four sub-passes over the pixel
//     parities (2 x 2 interleaving: 8 sub-passes for 2 passes, as the thesis); a pixel's candidates are its own
//     texel and, for each of its 3 x 3 neighbours q = p + d, q's texel and q's K analysis candidates, each shifted
//     by -d h_l, those of the admissible levels of the pixel's own level only (so a pixel at an exemplar's finest
//     level must move on: to a finer exemplar, or up its own stack through a loop); the best minimises, over the
//     5 x 5 Delta,
//       || (E(S[p + Delta]) + R_{p + Delta} - R_p) - (E^j_l[v + Delta h_l] + b) ||^2
//     (the synthesis neighbourhood brought back into the pixel's own colour space, against the candidate
//     transformed by its transfer b, Sec. 5.3), ties to the earliest in that order; the pixel then points at it
//     and R_p += b. With `correct_inconsistency` off, b is taken as 0 everywhere (to measure what it buys).
//     Loops are taken only from the finest level, matched at the source's contrast and carry a transfer that
//     fades by half per level (loop_transitions.h). Deviation [Han08]: a candidate texel that one of the pixel's 8
//     neighbours already holds on the same level is not taken (the same texel twice is a magnification, and a region of
//     one texel is its own best match at every later level: issue 18). Deviation [Han08]: at the output level T a pixel
//     at its exemplar's finest level may also keep a texel of that level (its own, or a neighbour's shifted), unless
//     it is a magnification (its parent was stuck there already: correction would shuffle the magnified texels into a
//     grid of squares). The thesis never admits E_L, so that correction moves on to finer scales; at T there is no
//     finer level to move on to, and forcing the move there shows every window that reaches an exemplar's own scale
//     through its coarser neighbour (a self-loop window at the exemplar's scale showed the exemplar minified 2x and
//     blurred: 3% of leather's block variance, 73% of bumps'; issue 18).
// Window independence: level t is computed on the requested region grown by 2 pixels per sub-pass (the 5 x 5
// reach), whose parents are computed the same way; reads beyond a region clamp to it and only affect pixels that
// are discarded, so every output pixel is a function of its position alone (tests: tiles vs whole, 1 vs 2 threads).
#pragma once

#include <cstdint>
#include <vector>

#include "formats/graph_layout.h"
#include "libbake/core/progress.h"
#include "libbake/image/image_io.h"

namespace mbk {

// A window lies within +-kMaxSynthesisCoordinate pixels: regions grow by padding and halve, with no overflow below it.
inline constexpr int64_t kMaxSynthesisCoordinate = int64_t(1) << 62;

struct SynthesisOptions {
  uint32_t level = 0;              // T
  int64_t x = 0, y = 0;            // window origin at level T (pixels; may be negative)
  uint32_t width = 1, height = 1;  // window size
  uint32_t seed = 1;
  std::vector<double> jitter = {1.0, 0.6, 0.4, 0.3};  // r_t, in [0, 1]; the last repeats
  uint32_t passes = 2;
  bool correct_inconsistency = true;
};

struct SynthesisStatistics {
  std::vector<double> matching_error;  // per level: mean over the window's region of the best Eq. 5.1 error / 25
};

// The window's colours (channels as the graph's exemplars); for a normal-map graph, unit +Y normals.
// Error(bad_command_line) for an empty window, a level above 40 or a jitter outside [0, 1].
Image synthesize_window(const GraphTables& graph, const SynthesisOptions& options, Progress& progress,
                        SynthesisStatistics* statistics = nullptr);

}  // namespace mbk
