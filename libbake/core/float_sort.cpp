// Linear-time float sorting (see float_sort.h).
#include "libbake/core/float_sort.h"

#include <array>
#include <cstdint>
#include <cstring>

namespace mbk {
namespace {

// Monotone map of float bits to unsigned integers: negatives (sign 1) reversed below positives.
uint32_t order_key(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}
float from_key(uint32_t k) {
  const uint32_t u = (k & 0x80000000u) ? (k & 0x7fffffffu) : ~k;
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

}  // namespace

void sort_floats(std::vector<float>& values) {
  constexpr int kBits = 11, kBuckets = 1 << kBits;
  std::vector<uint32_t> keys(values.size()), scratch(values.size());
  for (size_t i = 0; i < values.size(); ++i) keys[i] = order_key(values[i]);
  for (int shift = 0; shift < 32; shift += kBits) {  // 0, 11, 22: the last pass sees the top 10 bits
    std::array<size_t, kBuckets> start{};
    for (uint32_t k : keys) ++start[(k >> shift) & (kBuckets - 1)];
    size_t offset = 0;
    for (size_t& s : start) {
      const size_t count = s;
      s = offset;
      offset += count;
    }
    for (uint32_t k : keys) scratch[start[(k >> shift) & (kBuckets - 1)]++] = k;  // stable
    keys.swap(scratch);
  }
  for (size_t i = 0; i < values.size(); ++i) values[i] = from_key(keys[i]);
}

}  // namespace mbk
