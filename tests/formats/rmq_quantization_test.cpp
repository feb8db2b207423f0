// The conservative quantizer of the rmq kind (formats/rmq_quantization.h): stored bounds always contain the
// value and are within one quantum of it, the ends of the range are exact, codes and values are monotone
// (so min/max commute with quantization, which the RMQ bake relies on), and degenerate or extremely narrow
// ranges stay conservative with ordered codes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "formats/error.h"
#include "formats/rmq_quantization.h"
#include "libbake/core/hash.h"

namespace mbk {
namespace {

std::vector<RmqRange> ranges() {
  return {{-1.0, 1.0},        {-0.9, 0.7},    {-1.3, 1.3},         {0.1, 0.1000001}, {-2.7182818, -0.31830988},
          {-0.5, 0.5 + 1e-9}, {-1e-300, 0.0}, {0.25, 0.25 + 5e-16}};
}

TEST(RmqQuantization, BoundsContainTheValueWithinOneQuantum) {
  for (uint32_t bits : {8u, 16u})
    for (const RmqRange& r : ranges()) {
      const double quantum = r.quantum(bits);
      for (uint32_t i = 0; i < 20000; ++i) {
        // Random values, the ends, and values sitting exactly on a code.
        double v = r.lo + (r.hi - r.lo) * unit_from_hash(hash3(bits, i, 7));
        if (i == 0) v = r.lo;
        if (i == 1) v = r.hi;
        if (i % 5 == 2) v = rmq_dequantize(hash3(bits, i, 8) % (rmq_code_max(bits) + 1), r, bits);
        v = std::clamp(v, r.lo, r.hi);
        const uint32_t down = rmq_quantize_down(v, r, bits), up = rmq_quantize_up(v, r, bits);
        const double below = rmq_dequantize(down, r, bits), above = rmq_dequantize(up, r, bits);
        ASSERT_LE(below, v) << bits << " bits, [" << r.lo << ", " << r.hi << "], v = " << v;
        ASSERT_GE(above, v) << bits << " bits, [" << r.lo << ", " << r.hi << "], v = " << v;
        ASSERT_LE(down, up);
        // One quantum, up to the double rounding of lo + q * quantum.
        const double rounding = 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(r.lo), std::abs(r.hi));
        ASSERT_LE(v - below, quantum + rounding) << v;
        ASSERT_LE(above - v, quantum + rounding) << v;
        // Tightest: the next code in the safe direction would not bound v.
        if (up > 0) {
          ASSERT_LT(rmq_dequantize(up - 1, r, bits), v);
        }
      }
    }
}

TEST(RmqQuantization, EndsAreExactAndValuesNeverDecrease) {
  for (uint32_t bits : {8u, 16u})
    for (const RmqRange& r : ranges()) {
      EXPECT_EQ(rmq_dequantize(0, r, bits), r.lo);
      EXPECT_EQ(rmq_dequantize(rmq_code_max(bits), r, bits), r.hi);
      EXPECT_EQ(rmq_dequantize(rmq_quantize_up(r.hi, r, bits), r, bits), r.hi);
      EXPECT_EQ(rmq_quantize_down(r.lo, r, bits), 0u);
      for (uint32_t q = 1; q <= rmq_code_max(bits); ++q)
        ASSERT_LE(rmq_dequantize(q - 1, r, bits), rmq_dequantize(q, r, bits)) << q;
    }
}

TEST(RmqQuantization, QuantizersAreMonotoneSoMinMaxCommuteWithThem) {
  for (uint32_t bits : {8u, 16u})
    for (const RmqRange& r : ranges())
      for (uint32_t i = 0; i < 5000; ++i) {
        double a = r.lo + (r.hi - r.lo) * unit_from_hash(hash3(bits, i, 1));
        double b = r.lo + (r.hi - r.lo) * unit_from_hash(hash3(bits, i, 2));
        a = std::clamp(a, r.lo, r.hi), b = std::clamp(b, r.lo, r.hi);
        if (a > b) std::swap(a, b);
        ASSERT_LE(rmq_quantize_down(a, r, bits), rmq_quantize_down(b, r, bits));
        ASSERT_LE(rmq_quantize_up(a, r, bits), rmq_quantize_up(b, r, bits));
        EXPECT_EQ(std::min(rmq_quantize_down(a, r, bits), rmq_quantize_down(b, r, bits)),
                  rmq_quantize_down(std::min(a, b), r, bits));
      }
}

TEST(RmqQuantization, DegenerateRangeStoresTheValueExactly) {
  // A constant channel: lo == hi, every code reads the value itself.
  const RmqRange r{0.375, 0.375};
  for (uint32_t bits : {8u, 16u}) {
    EXPECT_EQ(rmq_quantize_down(0.375, r, bits), 0u);
    EXPECT_EQ(rmq_quantize_up(0.375, r, bits), 0u);
    EXPECT_EQ(rmq_dequantize(0, r, bits), 0.375);
    EXPECT_EQ(r.quantum(bits), 0.0);
  }
}

TEST(RmqQuantization, ValuesOutsideTheRangeAreAnInternalError) {
  const RmqRange r{-0.5, 0.5};
  EXPECT_THROW(rmq_quantize_up(0.6, r, 16), Error);
  EXPECT_THROW(rmq_quantize_down(-0.6, r, 8), Error);
  EXPECT_THROW(rmq_quantize_down(std::nan(""), r, 16), Error);
}

}  // namespace
}  // namespace mbk
