// Merging the vMF lobes a filtered lookup reads, by direction rather than by slot. [Han07] Alg. 7.2 blends a vMF
// pyramid slot by slot: slot j of every texel a lookup touches (its bilinear taps at two levels, over every
// anisotropic probe) is averaged as premultiplied (alpha, alpha r). That is right only where slot j holds the same
// lobe everywhere. Where it does not - a map whose texels are mostly one exact normal (flat ground: a lobe at the
// kappa cap, an atom) cut by features whose lobes take the other slots in varying order - the flat ground's atom
// is averaged with a bevel's lobe into one wide lobe, and at a grazing view a wide lobe shades several times darker
// than the atom it swallowed (measured on the filtering report's scifi_panel_bevels plane: a horizon pixel's
// specular 13.9 from the atom alone, 3.9 from the merged lobe of weight 0.92 and kappa 32; the fitted levels
// themselves keep the atom at weight 0.61-0.89, kappa 10^6).
//
// So the lookup gathers every tap's lobes as weighted candidates, grouped by texel, and merges them greedily into at
// most `max_lobes` lobes. The heaviest texel's lobes come first and each starts a lobe (they are its fit's separate
// components: a lookup at one texel returns its lobes unchanged). Then, texels by decreasing weight and each
// texel's lobes by decreasing weight, a candidate joins, among the lobes whose direction is within the two lobes'
// angular spreads of its own,
//     angle(mu_c, mu_k) <= s_c + s_k + kVmfMergeFloor,   s = sqrt(2 (1 - |r|)) (~ sqrt(2 / kappa), the vMF's spread),
// the one whose mass-weighted spread grows least, (a_c + a_k) s_(c+k) - a_c s_c - a_k s_k; else it starts a lobe of
// its own while there are fewer than max_lobes; else it joins the lobe of least growth among all (so a light
// feature is merged into another light one rather than into the heavy atom of the flat ground, whose spread would
// grow from 0 to the angle between them). Premultiplied moments add, so a lookup's total weight, resultant and
// features are those of the slot-wise blend; only their grouping into lobes differs. Lobes of one direction (atoms
// of the same normal) merge without widening; atoms of different normals stay atoms while slots last; smooth maps,
// whose lobes are wide and overlapping, merge as before. Deterministic: ties keep the order given.
#pragma once

#include <span>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/core/vmf_lobe.h"

namespace mbk {

inline constexpr double kVmfMergeFloor = 0.02;  // radians

// One candidate lobe: premultiplied weight w alpha, resultant w alpha r, and its F features w alpha y (may be empty).
struct WeightedVmfLobe {
  double alpha = 0.0;
  Vec3 alpha_r = Vec3::Zero();
  std::span<const double> alpha_y;
  size_t group = 0;  // the texel it comes from
};

// The merged lobes (at most max_lobes; empty lobes, alpha 0, fill the rest up to max_lobes) with their summed
// features (F per lobe, premultiplied: divide by the lobe's alpha) appended to `alpha_y` when it is non-null.
std::vector<VmfLobeShape> merge_vmf_lobes(std::span<const WeightedVmfLobe> candidates, size_t max_lobes,
                                          double kappa_max, size_t feature_count, std::vector<double>* alpha_y);

}  // namespace mbk
