// Sorting large arrays of floats in linear time: an LSD radix sort on the order-preserving integer image of each
// float (sign bit flipped for positives, all bits flipped for negatives), three passes of 11 bits. It gives the
// order of std::sort with operator< on non-NaN floats, except that -0 comes before +0 (std::sort leaves equal
// elements in any order); NaNs go after +inf (positive payloads) or before -inf (negative). Deterministic,
// single-threaded; needs a second buffer of the same size. Used where a bake sorts every texel value (the
// standardization LUTs): 4 M floats take a few tens of milliseconds instead of several hundred.
#pragma once

#include <vector>

namespace mbk {

void sort_floats(std::vector<float>& values);

}  // namespace mbk
