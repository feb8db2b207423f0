// libFuzzer target: JSON colour stops (libbake/colormap/colormap_source.h), read as `colormap` reads a .json
// source (parse_colormap_stops), with the file's own encoding and with each --encoding override. Any input must
// end in a colour curve or an mbk::Error, never a crash, a sanitizer report or a hang. Seeds:
// tests/fuzz/corpus/colormap/.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/error.h"
#include "libbake/colormap/colormap_source.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (mbk::ColorEncoding e : {mbk::ColorEncoding::automatic, mbk::ColorEncoding::srgb, mbk::ColorEncoding::linear}) {
    try {
      (void)mbk::parse_colormap_stops(text, "fuzz/stops.json", e);
    } catch (const mbk::Error&) {
    }
  }
  return 0;
}
