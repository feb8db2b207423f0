// libFuzzer target: the .mbk container and every kind's validator, through the paths every reader uses
// (validate_asset, which `validate` prints, and Asset::parse, which render, bake's freshness check and synth open
// assets with: the container checks, then the kind's invariants). Any input must end in findings or an mbk::Error,
// never a crash, a sanitizer report or a hang. Each input is tried as it is and, so that the fuzzer reaches the
// checks behind the checksums, once more with its header and section checksums recomputed wherever the header's
// regions lie inside the input. Seeds: tests/fuzz/corpus/asset/ (one small asset of each kind).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "formats/asset.h"
#include "formats/validate.h"
#include "tests/formats/reseal.h"

namespace {

void exercise(std::vector<uint8_t> bytes) {
  (void)mbk::validate_asset(bytes);
  try {
    mbk::Asset a = mbk::Asset::parse(std::move(bytes), "fuzz.mbk");
    for (const auto& s : a.sections()) (void)a.bytes_of(s);
  } catch (const mbk::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<uint8_t> bytes(data, data + size);
  exercise(bytes);
  exercise(mbk::test::resealed(std::move(bytes)));
  return 0;
}
