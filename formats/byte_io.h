// Little-endian integer reads and writes on byte buffers, for the container header and section table.
// Readers take an offset already bounds-checked by the caller.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

namespace mbk {

static_assert(std::endian::native == std::endian::little,
              "microbake stores sections as raw little-endian arrays; a big-endian port must byte-swap them");

template <typename T>
T load_le(const uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

template <typename T>
void store_le(uint8_t* p, T v) {
  std::memcpy(p, &v, sizeof(T));
}

inline uint64_t align_up(uint64_t v, uint64_t a) { return (v + a - 1) / a * a; }

}  // namespace mbk
