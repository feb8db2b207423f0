// libFuzzer target: the normal-map decode path after the image library (decode_normal_map in
// libbake/image/normal_map.h: texel decoding, invalid texels, repair, convention detection and the y flip), fed
// decoded pixel buffers of any size and value, NaN and Inf included, as load_image would hand them over for each
// stored type. Any input must end in a map or an mbk::Error, never a crash, a sanitizer report or a hang.
//
// Input layout (5 header bytes, then samples):
//   [0] width  = byte % 65 (0 to 64)       [1] height = byte % 65
//   [2] channels = 1 + byte % 4            [3] stored type = byte % 5: uint8, uint16, half, float, int8
//   [4] bits 0-1: convention (1 = +Y, 2 = -Y, else auto); bit 2: repair invalid texels
//   then the samples, little-endian in the stored type, converted as load_image converts them (unsigned integers
//   to [0, 1], int8 to [-1, 1], half and float as they are); they repeat when the input is shorter than the
//   buffer, and a buffer without samples is all zero. Seeds (tests/fuzz/corpus/normal_map/) are real maps in it.
#include <Imath/half.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "formats/error.h"
#include "libbake/image/normal_map.h"

namespace {

struct StoredType {
  const char* name;
  size_t bytes;
  bool is_float, is_signed;
  int integer_bits;
};
constexpr StoredType kTypes[] = {
    {"uint8", 1, false, false, 8}, {"uint16", 2, false, false, 16}, {"half", 2, true, false, 0},
    {"float", 4, true, false, 0},  {"int8", 1, false, true, 8},
};

float sample_value(const StoredType& t, const uint8_t* p) {
  if (t.bytes == 1) return t.is_signed ? std::max(-1.0f, int8_t(p[0]) / 127.0f) : p[0] / 255.0f;
  if (t.bytes == 2) {
    const uint16_t v = uint16_t(p[0] | (p[1] << 8));
    if (!t.is_float) return v / 65535.0f;
    Imath::half h;
    h.setBits(v);
    return float(h);
  }
  float f;
  std::memcpy(&f, p, sizeof f);  // the bytes are little-endian on every machine we build on
  return f;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 5) return 0;
  const StoredType& type = kTypes[data[3] % 5];
  mbk::Image image;
  image.width = data[0] % 65;
  image.height = data[1] % 65;
  image.channels = 1 + data[2] % 4;
  mbk::ImageFileInfo info;
  info.pixel_format = type.name;
  info.is_float = type.is_float;
  info.is_signed = type.is_signed;
  info.integer_bits = type.integer_bits;
  info.file_channels = image.channels;
  mbk::NormalMapLoadOptions options;
  if ((data[4] & 3) == 1) options.convention = mbk::YConvention::plus_y;
  if ((data[4] & 3) == 2) options.convention = mbk::YConvention::minus_y;
  options.invalid = (data[4] & 4) ? mbk::InvalidTexelPolicy::repair : mbk::InvalidTexelPolicy::error;

  const uint8_t* samples = data + 5;
  const size_t count = (size - 5) / type.bytes;
  image.pixels.resize(size_t(image.width) * image.height * image.channels, 0.0f);
  for (size_t i = 0; count && i < image.pixels.size(); ++i)
    image.pixels[i] = sample_value(type, samples + (i % count) * type.bytes);
  try {
    (void)mbk::decode_normal_map(image, info, options, "fuzz.png");
  } catch (const mbk::Error&) {
  }
  return 0;
}
