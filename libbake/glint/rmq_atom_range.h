// The quantization range of an RMQ table chosen so that one value - the example's flat ground - is stored
// exactly (a writer's choice within formats/SPEC.md "Kind 3: rmq": any [lo, hi] containing the data is valid).
//
// Why: where a map is mostly one value x0 (flat ground: the atom of the standardization LUT), every texel of the
// plateau has the leaf interval [x0, x0]. Quantized outward with the data's own range it becomes
// [x0 - a, x0 + b], a, b < one quantum, and under histogram blending that is a disaster for the range query:
// G rises steeply on both sides of an atom, so G(x0 - a) and G(x0 + b) lie at the atom's two rank ends
// (e.g. -1.8 and +1.8 for a 93% atom) instead of at G(x0), and every plateau node's blended bound spans the
// atom's whole rise; such nodes are neither pruned nor aggregated (glint_pndf.h). With x0 exactly a code, the
// plateau's bounds are [x0, x0] in every blend mode.
//
// The range: a quantum D >= the data's (hi_d - lo_d) / (Q - 1) rounded UP to kRmqAtomQuantumBits significant
// bits (so that small multiples of it are exact in double), the code q0 = ceil((x0 - lo_d) / D), and
// lo = x0 - q0 D, hi = lo + Q D. Then lo <= lo_d, hi >= hi_d (one spare quantum covers the shift), the quantum
// (hi - lo) / Q is D again, and value(q0) = lo + q0 D = x0 - each step exact in double for normal components.
// The result is checked through the reader's own formula (RmqQuantizer::value); when any step is not exact
// (values so small or so spread that the bits do not fit, a constant channel) the data's range is used as is.
// Cost: the quantum grows by a factor (Q / (Q - 1)) (1 + 2^-7) at most: bounds at most 0.8% + 1/Q looser.
#pragma once

#include <cstdint>
#include <optional>

#include "formats/rmq_quantization.h"

namespace mbk {

inline constexpr int kRmqAtomQuantumBits = 8;

// [lo, hi] containing `data` in which `atom` (inside `data`) is the value of a code, or `data` itself when the
// atom is absent, outside `data`, or cannot be made exact (rules above).
RmqRange rmq_range_with_exact_value(const RmqRange& data, std::optional<double> atom, uint32_t bits);

}  // namespace mbk
