// libFuzzer target: crease curves in SVG (libbake/crease/curve_set.h, parse_svg_curves); see fuzz_curves.h.
// Seeds: tests/fuzz/corpus/curves_svg/.
#include "tests/fuzz/fuzz_curves.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mbk::fuzz::exercise_curves(mbk::parse_svg_curves, data, size);
  return 0;
}
