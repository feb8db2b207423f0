// libFuzzer target: crease curves in JSON (libbake/crease/curve_set.h, parse_json_curves); see fuzz_curves.h.
// Seeds: tests/fuzz/corpus/curves_json/.
#include "tests/fuzz/fuzz_curves.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mbk::fuzz::exercise_curves(mbk::parse_json_curves, data, size);
  return 0;
}
