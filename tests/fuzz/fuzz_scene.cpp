// libFuzzer target: scene files (libbake/scene/scene.h), read as `render` and `bake` read them
// (parse_scene_text: strict JSON, then every key, shape, material, effect and light). Any input must end in a
// Scene or an mbk::Error, never a crash, a sanitizer report or a hang. Seeds: tests/fuzz/corpus/scene/.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/error.h"
#include "libbake/scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    (void)mbk::parse_scene_text(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz/scene.json");
  } catch (const mbk::Error&) {
  }
  return 0;
}
