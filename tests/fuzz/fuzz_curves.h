// The body both curve targets share (fuzz_curves_json.cpp, fuzz_curves_svg.cpp): parse the input as curves for a
// map of 64 x 64 texels, as `crease` and the crease effect do, and then cut the result into segments (what the
// crease bake consumes). Any input must end in curves or an mbk::Error, never a crash, a sanitizer report or a hang.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "formats/error.h"
#include "libbake/crease/curve_set.h"

namespace mbk::fuzz {

using CurveParser = CurveSet (*)(const std::string& text, const std::string& file, uint32_t width, uint32_t height);

inline void exercise_curves(CurveParser parse, const uint8_t* data, size_t size) {
  try {
    const CurveSet curves = parse(std::string(reinterpret_cast<const char*>(data), size), "fuzz", 64, 64);
    (void)curve_segments(curves);
  } catch (const Error&) {
  }
}

}  // namespace mbk::fuzz
